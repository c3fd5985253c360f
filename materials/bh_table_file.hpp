#pragma once
// B-H tables in CSV files: `bh_file: steel.csv` in a case's material, and the export of a
// curve in the same format (`magfem materials --export NAME`, cli/materials_command.hpp).
//
// Format: one row per line, two comma-separated columns. Either a header naming them,
// `H_Apm,B_T` or `B_T,H_Apm` (H in A/m, B in T), or no header and the columns H, B in that
// order. Blank lines and lines starting with '#' are skipped; spaces around values, CRLF line
// ends and a UTF-8 byte-order mark are accepted. Numbers follow the case file's rule
// (parse_number), so a file table gives the same curve as the same inline table, bit for bit.
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/yaml_node.hpp"
#include "materials/bh_curve.hpp"

namespace magfem {

// The rows of a B-H table file, in file order, and the 1-based line each came from.
struct BhTableRows {
  std::vector<double> h_Apm;
  std::vector<double> b_T;
  std::vector<int> line;
};

// Reads the CSV file `path`. Problems inside it are InputErrors naming `path`, the line and
// (for a bad value) the column, with `context` appended to the message; an unreadable file is
// an InputError naming `path` alone.
BhTableRows read_bh_table_file(const std::string& path, const std::string& context);

// The curve of a material's `bh_file:` node: the path is relative to the directory of the
// case file. An unreadable file is reported at the node (case file, line, field); a bad row,
// including one BhCurve refuses, at the CSV file's line, naming the field in the message.
std::shared_ptr<const BhCurve> load_bh_table_file(const YamlNode& bh_file);

// Writes the curve's table (origin included) with the header H_Apm,B_T and the shortest
// decimal form of each number that reads back to the same double.
void write_bh_table_file(std::ostream& out, const BhCurve& curve);

} // namespace magfem
