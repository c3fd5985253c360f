#include "pipeline/build_info.hpp"

#include <system_error>

#include <dlfcn.h>

namespace magfem {

namespace build_info {
extern const char* const version; // build_info_values.cpp, generated at build time
extern const char* const commit;
} // namespace build_info

std::string magfem_version() {
  return build_info::version;
}
std::string magfem_git_commit() {
  return build_info::commit;
}

void add_provenance(nlohmann::ordered_json& summary) {
  summary["magfem_version"] = magfem_version();
  summary["commit"] = magfem_git_commit();
}

namespace {

// <dir>/share/magfem if it is a directory.
std::optional<std::filesystem::path> share_under(const std::filesystem::path& dir) {
  std::error_code ec;
  const auto share = dir / "share" / "magfem";
  if (std::filesystem::is_directory(share, ec))
    return share;
  return std::nullopt;
}

} // namespace

std::optional<std::filesystem::path> installed_data_dir() {
  // Inside the Python module (<prefix>/lib/python3/dist-packages/magfem/_core*.so, or wherever
  // MAGFEM_PYTHON_INSTALL_DIR put it) the process is python3, whose path says nothing about
  // magfem's prefix: the module's own file does, a few folders up. Looked at first, so that a
  // module installed in a prefix of its own is not served another install's /usr/share.
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&installed_data_dir), &info) != 0 && info.dli_fname &&
      info.dli_fname[0] == '/' && (ec || !std::filesystem::equivalent(info.dli_fname, exe, ec))) {
    auto dir = std::filesystem::path(info.dli_fname).parent_path();
    for (int up = 0; up < 5 && dir.has_relative_path(); ++up, dir = dir.parent_path())
      if (auto share = share_under(dir))
        return share;
  }
  if (ec)
    return std::nullopt;
  return share_under(exe.parent_path().parent_path()); // <prefix>/bin/magfem
}

} // namespace magfem
