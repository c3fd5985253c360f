#pragma once
// A probe's samples as a table with named columns, written as CSV (header row, then one row
// per sample; numbers with 10 significant digits).
#include <string>
#include <vector>

namespace magfem {

struct ProbeTable {
  std::string name;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  std::string to_csv() const;
  // Column index by name; throws std::out_of_range if absent.
  std::size_t column(const std::string& name) const;
};

} // namespace magfem
