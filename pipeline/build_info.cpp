#include "pipeline/build_info.hpp"

#include <system_error>

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

std::optional<std::filesystem::path> installed_data_dir() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec)
    return std::nullopt;
  const auto share = exe.parent_path().parent_path() / "share" / "magfem";
  if (std::filesystem::is_directory(share, ec))
    return share;
  return std::nullopt;
}

} // namespace magfem
