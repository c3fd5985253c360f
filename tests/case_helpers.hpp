#pragma once
// Helpers for app-level tests: run example cases in-process and compare probes with exact
// fields.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/run2d.hpp"
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

// The entry called `name` of a run's forces (or anything with a `name`); throws if none.
template <class Named>
const Named& named(const std::vector<Named>& entries, const std::string& name) {
  for (const auto& e : entries)
    if (e.name == name)
      return e;
  throw std::runtime_error("no entry named " + name);
}

inline const ProbeTable& probe(const Run2D& run, const std::string& name) {
  for (const auto& p : run.probes)
    if (p.name == name)
      return p;
  throw std::runtime_error("no probe " + name);
}

} // namespace magfem::test
