#include "materials/bh_table_file.hpp"

#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <optional>

namespace magfem {

namespace {

constexpr const char* h_name = "H_Apm";
constexpr const char* b_name = "B_T";

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos)
    return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// The comma-separated fields of a line, trimmed.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const auto comma = line.find(',', start);
    out.push_back(trimmed(line.substr(start, comma - start)));
    if (comma == std::string::npos)
      return out;
    start = comma + 1;
  }
}

// Reads a table file line by line; remembers which column holds H.
class TableReader {
public:
  TableReader(std::string path, std::string context)
      : path_(std::move(path)), context_(std::move(context)) {}

  BhTableRows read() {
    std::ifstream in(path_);
    if (!in)
      throw InputError(path_, 0, "", "cannot open the B-H table file" + context_);
    std::string text;
    for (int number = 1; std::getline(in, text); ++number) {
      if (number == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0)
        text.erase(0, 3); // UTF-8 byte-order mark (spreadsheet exports)
      if (!text.empty() && text.back() == '\r')
        text.pop_back();
      const std::string line = trimmed(text);
      if (!line.empty() && line.front() != '#')
        take(line, number);
    }
    if (rows_.h_Apm.size() < 2)
      fail(rows_.line.empty() ? 0 : rows_.line.back(), "",
           "a B-H table needs at least 2 rows, got " + std::to_string(rows_.h_Apm.size()));
    return std::move(rows_);
  }

private:
  std::string path_, context_;
  BhTableRows rows_;
  bool first_ = true;
  int h_column_ = 0;

  [[noreturn]] void fail(int line, const std::string& field, const std::string& message) const {
    throw InputError(path_, line, field, message + context_);
  }

  void take(const std::string& line, int number) {
    const auto f = fields_of(line);
    if (f.size() != 2)
      fail(number, "",
           "expected 2 comma-separated columns (H in A/m, B in T), got " +
               std::to_string(f.size()));
    const bool is_first = first_;
    first_ = false;
    if (is_first && (!parse_number(f[0]) || !parse_number(f[1]))) {
      read_header(f, number);
      return;
    }
    const std::array<const char*, 2> names{h_column_ == 0 ? h_name : b_name,
                                           h_column_ == 0 ? b_name : h_name};
    std::array<double, 2> v{};
    for (int c = 0; c < 2; ++c) {
      const auto value = parse_number(f[c]);
      if (!value)
        fail(number, names[c], "expected a number, got '" + f[c] + "'");
      v[c] = *value;
    }
    rows_.h_Apm.push_back(v[h_column_]);
    rows_.b_T.push_back(v[1 - h_column_]);
    rows_.line.push_back(number);
  }

  void read_header(const std::vector<std::string>& f, int number) {
    if (f[0] == h_name && f[1] == b_name)
      h_column_ = 0;
    else if (f[0] == b_name && f[1] == h_name)
      h_column_ = 1;
    else
      fail(number, "",
           "the header must name the columns H_Apm and B_T (H in A/m, B in T) in either order, "
           "got '" +
               f[0] + "," + f[1] + "'; without a header the columns are H, B (numbers only)");
  }
};

} // namespace

BhTableRows read_bh_table_file(const std::string& path, const std::string& context) {
  return TableReader(path, context).read();
}

std::shared_ptr<const BhCurve> load_bh_table_file(const YamlNode& bh_file) {
  const std::filesystem::path given(bh_file.as_string());
  const std::filesystem::path path =
      given.is_absolute() ? given : std::filesystem::path(bh_file.file()).parent_path() / given;
  const std::string context = " (read for " + bh_file.path() + " at " + bh_file.file() + ":" +
                              std::to_string(bh_file.line()) + ")";
  if (!std::filesystem::is_regular_file(path))
    bh_file.fail("cannot read the B-H table file '" + path.string() +
                 "' (a relative path is taken from the case file's directory)");
  BhTableRows rows = read_bh_table_file(path.string(), context);
  const std::vector<int> lines = rows.line;
  try {
    check_bh_table_plausible(rows.h_Apm, rows.b_T);
    return std::make_shared<const BhCurve>(std::move(rows.h_Apm), std::move(rows.b_T));
  } catch (const BhTableError& e) {
    throw InputError(path.string(), e.row() < lines.size() ? lines[e.row()] : 0, "",
                     e.reason() + context);
  }
}

void write_bh_table_file(std::ostream& out, const BhCurve& curve) {
  const auto shortest = [](double v) {
    std::array<char, 64> buf{};
    return std::string(buf.data(), std::to_chars(buf.data(), buf.data() + buf.size(), v).ptr);
  };
  out << h_name << ',' << b_name << '\n';
  for (std::size_t i = 0; i < curve.h_table().size(); ++i)
    out << shortest(curve.h_table()[i]) << ',' << shortest(curve.b_table()[i]) << '\n';
}

} // namespace magfem
