#pragma once
// What built this binary and where its data lives: the provenance every output records and the
// lookup that lets an installed magfem find its share/ directory without build-tree paths.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace magfem {

// Semantic version from CMake's project(VERSION ...).
std::string magfem_version();
// The git commit the binary was built from ("-dirty" when tracked files differed; "unknown"
// outside a git checkout).
std::string magfem_git_commit();

// Adds magfem_version and commit to a summary, so a result names the code that produced it.
void add_provenance(nlohmann::ordered_json& summary);

// <prefix>/share/magfem when this executable runs from <prefix>/bin, or the Python module
// lies a few folders under <prefix> (lib/python3/dist-packages/magfem), and that directory
// exists (an installed magfem); nothing when it runs from a build tree.
std::optional<std::filesystem::path> installed_data_dir();

} // namespace magfem
