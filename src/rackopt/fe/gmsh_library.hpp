// Gmsh's C API (gmshc.h, Debian libgmsh-dev), opened with dlopen at the first
// mesh and not linked: libgmsh pulls in about a hundred shared libraries
// (OpenCASCADE, FLTK, MUMPS, ...) whose loading costs a quarter of a second
// at every start of every program that links it, while only the FE tier
// meshes. A run that never meshes never loads Gmsh.
#pragma once

#include <stdexcept>
#include <string>

#include <gmshc.h>

namespace rackopt::fe {

// The Gmsh library could not be opened or lacks a function rackopt uses: the
// message names the library looked for, the loader's reason and the Debian
// package that provides it.
class GmshNotFound : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The C API functions the mesher calls, resolved from the opened library.
struct GmshApi {
  decltype(&gmshInitialize) initialize = nullptr;
  decltype(&gmshFinalize) finalize = nullptr;
  decltype(&gmshOptionSetNumber) option_set_number = nullptr;
  decltype(&gmshModelAdd) model_add = nullptr;
  decltype(&gmshModelGeoAddPoint) geo_add_point = nullptr;
  decltype(&gmshModelGeoAddLine) geo_add_line = nullptr;
  decltype(&gmshModelGeoAddCurveLoop) geo_add_curve_loop = nullptr;
  decltype(&gmshModelGeoAddPlaneSurface) geo_add_plane_surface = nullptr;
  decltype(&gmshModelGeoSynchronize) geo_synchronize = nullptr;
  decltype(&gmshModelAddPhysicalGroup) add_physical_group = nullptr;
  decltype(&gmshModelMeshFieldAdd) field_add = nullptr;
  decltype(&gmshModelMeshFieldSetString) field_set_string = nullptr;
  decltype(&gmshModelMeshFieldSetNumbers) field_set_numbers = nullptr;
  decltype(&gmshModelMeshFieldSetAsBackgroundMesh) field_set_as_background_mesh = nullptr;
  decltype(&gmshModelMeshGenerate) mesh_generate = nullptr;
  decltype(&gmshModelMeshGetElementsByType) get_elements_by_type = nullptr;
  decltype(&gmshModelMeshGetNodes) get_nodes = nullptr;
  decltype(&gmshModelMeshGetNodesForPhysicalGroup) get_nodes_for_physical_group = nullptr;
  decltype(&gmshLoggerGetLastError) logger_get_last_error = nullptr;
  decltype(&gmshFree) free = nullptr;
};

// The library opened and resolved once per process (thread-safe); later
// calls return the same table. The library is $RACKOPT_GMSH_LIBRARY when set
// (a path or a name for the loader), else the one rackopt was built against
// (gmsh_library_name()). Throws GmshNotFound; a failed attempt is not
// retried within the process.
const GmshApi& gmsh_api();

// The library name gmsh_api() opens when RACKOPT_GMSH_LIBRARY is not set.
std::string gmsh_library_name();

// Whether this process has opened Gmsh (gmsh_api() succeeded).
bool gmsh_loaded();

}  // namespace rackopt::fe
