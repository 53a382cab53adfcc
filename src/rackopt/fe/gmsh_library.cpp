#include "rackopt/fe/gmsh_library.hpp"

#include <dlfcn.h>

#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>

#ifndef RACKOPT_GMSH_SONAME
#define RACKOPT_GMSH_SONAME "libgmsh.so"
#endif

namespace rackopt::fe {
namespace {

std::once_flag g_once;
GmshApi g_api;
std::exception_ptr g_error;
std::atomic<bool> g_loaded{false};

template <class F>
void resolve(void* handle, const char* symbol, const std::string& library, F& slot) {
  void* p = ::dlsym(handle, symbol);
  if (!p) {
    throw GmshNotFound("Gmsh library " + library + " has no function " + symbol +
                       ": rackopt needs the Gmsh 4.8 C API (Debian package libgmsh-dev)");
  }
  slot = reinterpret_cast<F>(p);
}

void open_gmsh() {
  const char* env = std::getenv("RACKOPT_GMSH_LIBRARY");
  const std::string library = env && *env ? env : gmsh_library_name();
  // RTLD_LOCAL: Gmsh's dependencies stay out of the global namespace.
  void* handle = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    throw GmshNotFound("Gmsh library " + library + " not found (" + (why ? why : "dlopen failed") +
                       "): the FE tier meshes with Gmsh; install the Debian package libgmsh-dev (./dev.sh does)" +
                       (env && *env ? ", or unset RACKOPT_GMSH_LIBRARY" : ""));
  }
  GmshApi api;
  resolve(handle, "gmshInitialize", library, api.initialize);
  resolve(handle, "gmshFinalize", library, api.finalize);
  resolve(handle, "gmshOptionSetNumber", library, api.option_set_number);
  resolve(handle, "gmshModelAdd", library, api.model_add);
  resolve(handle, "gmshModelGeoAddPoint", library, api.geo_add_point);
  resolve(handle, "gmshModelGeoAddLine", library, api.geo_add_line);
  resolve(handle, "gmshModelGeoAddCurveLoop", library, api.geo_add_curve_loop);
  resolve(handle, "gmshModelGeoAddPlaneSurface", library, api.geo_add_plane_surface);
  resolve(handle, "gmshModelGeoSynchronize", library, api.geo_synchronize);
  resolve(handle, "gmshModelAddPhysicalGroup", library, api.add_physical_group);
  resolve(handle, "gmshModelMeshFieldAdd", library, api.field_add);
  resolve(handle, "gmshModelMeshFieldSetString", library, api.field_set_string);
  resolve(handle, "gmshModelMeshFieldSetNumbers", library, api.field_set_numbers);
  resolve(handle, "gmshModelMeshFieldSetAsBackgroundMesh", library, api.field_set_as_background_mesh);
  resolve(handle, "gmshModelMeshGenerate", library, api.mesh_generate);
  resolve(handle, "gmshModelMeshGetElementsByType", library, api.get_elements_by_type);
  resolve(handle, "gmshModelMeshGetNodes", library, api.get_nodes);
  resolve(handle, "gmshModelMeshGetNodesForPhysicalGroup", library, api.get_nodes_for_physical_group);
  resolve(handle, "gmshLoggerGetLastError", library, api.logger_get_last_error);
  resolve(handle, "gmshFree", library, api.free);
  g_api = api;  // the handle stays open for the life of the process
  g_loaded = true;
}

}  // namespace

std::string gmsh_library_name() { return RACKOPT_GMSH_SONAME; }

const GmshApi& gmsh_api() {
  std::call_once(g_once, [] {
    try {
      open_gmsh();
    } catch (...) {
      g_error = std::current_exception();
    }
  });
  if (g_error) std::rethrow_exception(g_error);
  return g_api;
}

bool gmsh_loaded() { return g_loaded.load(); }

}  // namespace rackopt::fe
