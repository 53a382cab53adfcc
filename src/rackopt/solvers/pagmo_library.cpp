#include "rackopt/solvers/pagmo_library.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <mutex>
#include <system_error>

#ifndef RACKOPT_PAGMO_MODULE_FILE
#define RACKOPT_PAGMO_MODULE_FILE "librackopt_pagmo.so"
#endif
#ifndef RACKOPT_INSTALL_LIBDIR
#define RACKOPT_INSTALL_LIBDIR "lib"
#endif
#ifndef RACKOPT_INSTALL_PREFIX
#define RACKOPT_INSTALL_PREFIX "/usr/local"
#endif

namespace rackopt::solvers {
namespace {

namespace fs = std::filesystem;

constexpr const char* kEnv = "RACKOPT_PAGMO_MODULE";

std::once_flag g_once;
const pagmo_module::Api* g_api = nullptr;
std::exception_ptr g_error;

// The folder of the object (program or shared library) holding this code.
fs::path folder_of_this_code() {
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&pagmo_module_candidates), &info) == 0 || !info.dli_fname ||
      info.dli_fname[0] != '/')
    return {};  // the program itself: dladdr gives argv[0], /proc/self/exe covers it
  return fs::path(info.dli_fname).parent_path();
}

fs::path folder_of_program() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

void open_module() {
  const char* env = std::getenv(kEnv);
  const std::vector<std::string> candidates = pagmo_module_candidates();
  std::string tried;
  void* handle = nullptr;
  for (const std::string& file : candidates) {
    // A path is opened only when it exists (dlopen of a missing absolute path
    // would only say so); the bare file name goes to the dynamic linker.
    std::error_code ec;
    if (file.find('/') != std::string::npos && !fs::exists(file, ec) && !(env && *env)) {
      tried += "\n  " + file + " (no such file)";
      continue;
    }
    // RTLD_LOCAL: pagmo's symbols stay out of the global namespace.
    handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle) break;
    const char* why = ::dlerror();
    tried += "\n  " + file + " (" + (why ? why : "dlopen failed") + ")";
  }
  const std::string fix =
      env && *env ? std::string("\nset ") + kEnv + " to the path of librackopt_pagmo.so of this rackopt build, or unset it"
                  : std::string("\nbuild the target rackopt_pagmo (./dev.sh build does) or install rackopt, or set ") +
                        kEnv + " to the path of librackopt_pagmo.so";
  if (!handle)
    throw PagmoModuleNotFound("pagmo algorithms need rackopt's pagmo module (librackopt_pagmo.so, which links "
                              "libpagmo of the Debian package libpagmo-dev); not found:" +
                              tried + fix);
  using Entry = const pagmo_module::Api* (*)();
  const auto entry = reinterpret_cast<Entry>(::dlsym(handle, pagmo_module::kEntrySymbol));
  const pagmo_module::Api* api = entry ? entry() : nullptr;
  if (!api || api->abi != pagmo_module::kAbi || !api->start || !api->hypervolume)
    throw PagmoModuleNotFound(std::string("the pagmo module that was found belongs to another rackopt build "
                                          "(no matching ") +
                              pagmo_module::kEntrySymbol + ", interface " + std::to_string(pagmo_module::kAbi) +
                              ")" + fix);
  g_api = api;  // the handle stays open for the life of the process
}

}  // namespace

std::vector<std::string> pagmo_module_candidates() {
  const char* env = std::getenv(kEnv);
  if (env && *env) return {env};
  std::vector<std::string> out;
  const auto add = [&](const fs::path& p) {
    const std::string s = p.lexically_normal().string();
    for (const std::string& o : out)
      if (o == s) return;
    out.push_back(s);
  };
  for (const fs::path& dir : {folder_of_program(), folder_of_this_code()}) {
    if (dir.empty()) continue;
    add(dir / RACKOPT_PAGMO_MODULE_FILE);
    add(dir / ".." / "lib" / RACKOPT_PAGMO_MODULE_FILE);
    add(dir / ".." / RACKOPT_INSTALL_LIBDIR / RACKOPT_PAGMO_MODULE_FILE);
  }
  add(fs::path(RACKOPT_INSTALL_PREFIX) / RACKOPT_INSTALL_LIBDIR / RACKOPT_PAGMO_MODULE_FILE);
  out.emplace_back(RACKOPT_PAGMO_MODULE_FILE);
  return out;
}

const pagmo_module::Api& pagmo_api() {
  std::call_once(g_once, [] {
    try {
      open_module();
    } catch (...) {
      g_error = std::current_exception();
    }
  });
  if (g_error) std::rethrow_exception(g_error);
  return *g_api;
}

}  // namespace rackopt::solvers
