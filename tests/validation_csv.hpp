#pragma once
// results.csv of `magfem validate` without its `seconds` column (the time of each entry,
// which a rerun does not reproduce), for tests comparing two runs' tables. The columns after
// `seconds` (passes, unknowns, converged: validation/validate_report.hpp) hold no commas, so
// the column is found counting from the end of the line (earlier cells may be quoted).
#include <sstream>
#include <string>

namespace magfem::test {

// Columns after `seconds` in results.csv.
inline constexpr int validation_columns_after_seconds = 3;

inline std::string validation_csv_without_seconds(const std::string& csv) {
  std::stringstream in(csv);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::size_t end = line.size(); // the comma after `seconds`
    for (int i = 0; i < validation_columns_after_seconds && end != std::string::npos; ++i)
      end = line.rfind(',', end - 1);
    const std::size_t begin = end == std::string::npos ? end : line.rfind(',', end - 1);
    out += (begin == std::string::npos ? line : line.substr(0, begin) + line.substr(end)) + "\n";
  }
  return out;
}

} // namespace magfem::test
