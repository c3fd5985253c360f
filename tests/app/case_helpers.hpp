#pragma once
// Helpers for app-level tests: run example cases in-process and compare probes with exact
// fields.
#include <filesystem>
#include <fstream>
#include <string>

#include "app/run2d.hpp"
#include "tests/test_paths.hpp"

namespace magfem::test {

inline std::string example(const std::string& relative) {
  return std::string(magfem::test::source_dir()) + "/examples/" + relative;
}

// Writes `text` to a fresh temporary case file and returns its path.
inline std::string write_temp_case(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "magfem_tests";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

inline const ProbeTable& probe(const Run2D& run, const std::string& name) {
  for (const auto& p : run.probes)
    if (p.name == name)
      return p;
  throw std::runtime_error("no probe " + name);
}

} // namespace magfem::test
