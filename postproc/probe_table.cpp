#include "postproc/probe_table.hpp"

#include <cstdio>
#include <stdexcept>

namespace magfem {

std::string ProbeTable::to_csv() const {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + columns[i];
  out += "\n";
  char buf[40];
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%s%.10g", i ? "," : "", row[i]);
      out += buf;
    }
    out += "\n";
  }
  return out;
}

std::size_t ProbeTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::out_of_range("no column " + name);
}

} // namespace magfem
