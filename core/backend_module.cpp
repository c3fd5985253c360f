#include "core/backend_module.hpp"

#include <dlfcn.h>
#include <link.h>

#include <filesystem>
#include <sstream>

namespace magfem {
namespace {

// The directories of the run path of the object holding this code (the executable, or the
// Python module), where the modules belong, with $ORIGIN expanded: the loader searched them
// (and LD_LIBRARY_PATH and the system directories, left out of the message). Read from the
// object's dynamic section, since glibc's dlinfo(RTLD_DI_SERINFO) leaves RUNPATH out.
std::string searched_directories() {
  Dl_info info{};
  link_map* map = nullptr;
  if (!dladdr1(reinterpret_cast<void*>(&searched_directories), &info,
               reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) ||
      !map)
    return "";
  const char* strings = nullptr;
  const ElfW(Dyn)* run_path = nullptr;
  for (const ElfW(Dyn)* d = map->l_ld; d->d_tag != DT_NULL; ++d)
    if (d->d_tag == DT_STRTAB)
      strings = reinterpret_cast<const char*>(d->d_un.d_ptr); // relocated by the loader
    else if (d->d_tag == DT_RUNPATH || d->d_tag == DT_RPATH)
      run_path = d;
  if (!strings || !run_path)
    return "";
  std::error_code ignored; // the executable's link map has no name
  const std::filesystem::path object =
      map->l_name && *map->l_name ? std::filesystem::path(map->l_name)
                                  : std::filesystem::read_symlink("/proc/self/exe", ignored);
  const std::string origin = object.parent_path().string();
  std::string dirs;
  std::istringstream entries(strings + run_path->d_un.d_val);
  for (std::string dir; std::getline(entries, dir, ':');) {
    if (dir.empty())
      continue;
    for (const std::string token : {"${ORIGIN}", "$ORIGIN"})
      for (std::size_t at; (at = dir.find(token)) != std::string::npos;)
        dir.replace(at, token.size(), origin);
    dirs += (dirs.empty() ? "" : ", ") + std::filesystem::path(dir).lexically_normal().string();
  }
  return dirs;
}

} // namespace

void* open_backend_module(const std::string& file_name, const std::string& entry,
                          const std::string& needed_for) {
  // RTLD_LOCAL: the module's own copies of our library code stay its own.
  void* handle = dlopen(file_name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* reason = dlerror(); // copied: the loader reuses its buffer for the next error
    const std::string why = reason ? reason : "unknown reason";
    const std::string dirs = searched_directories();
    throw BackendModuleError("cannot load " + file_name + ", needed for " + needed_for +
                             (dirs.empty() ? "" : " (looked in " + dirs + ")") + ": " + why +
                             "; magfem's installation is incomplete");
  }
  using Entry = void* (*)();
  auto* make = reinterpret_cast<Entry>(dlsym(handle, entry.c_str()));
  if (!make)
    throw BackendModuleError(file_name + " lacks its entry point " + entry +
                             " (a module of another magfem version?)");
  return make();
}

} // namespace magfem
