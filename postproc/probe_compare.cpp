#include "postproc/probe_compare.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/input_error.hpp"

namespace magfem {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ','))
    out.push_back(cell);
  return out;
}

// Files written on Windows end their lines in "\r\n".
void strip_carriage_return(std::string& line) {
  if (!line.empty() && line.back() == '\r')
    line.pop_back();
}

bool is_field_component(const std::string& c) {
  return !c.empty() && c[0] == 'B';
}

} // namespace

ProbeTable read_probe_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(path, 0, "", "cannot open the file");
  return read_probe_csv(in, path);
}

ProbeTable read_probe_csv(std::istream& in, const std::string& path) {
  ProbeTable t;
  std::string line;
  if (!std::getline(in, line))
    throw InputError(path, 1, "", "empty file");
  strip_carriage_return(line);
  t.columns = split(line);
  if (t.columns.empty())
    throw InputError(path, 1, "", "the header names no columns");
  for (std::size_t i = 0; i < t.columns.size(); ++i) {
    if (t.columns[i].empty())
      throw InputError(path, 1, "", "column " + std::to_string(i + 1) + " has no name");
    // compare_probes looks columns up by name: a second one would never be compared.
    for (std::size_t j = 0; j < i; ++j)
      if (t.columns[j] == t.columns[i])
        throw InputError(path, 1, t.columns[i], "the column appears twice");
  }
  int n = 1;
  while (std::getline(in, line)) {
    ++n;
    strip_carriage_return(line);
    if (line.empty())
      continue;
    const auto cells = split(line);
    if (cells.size() != t.columns.size())
      throw InputError(path, n, "", "expected " + std::to_string(t.columns.size()) + " values");
    std::vector<double> row;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      try {
        std::size_t used = 0;
        row.push_back(std::stod(cells[i], &used));
        if (used != cells[i].size() || !std::isfinite(row.back()))
          throw std::invalid_argument(cells[i]);
      } catch (const std::exception&) {
        throw InputError(path, n, t.columns[i], "not a finite number: '" + cells[i] + "'");
      }
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::vector<ComponentComparison> compare_probes(const ProbeTable& ref, const ProbeTable& test) {
  if (ref.rows.size() != test.rows.size())
    throw std::invalid_argument("the probes have different numbers of points (" +
                                std::to_string(ref.rows.size()) + " and " +
                                std::to_string(test.rows.size()) + ")");
  // Same sample points: compare the coordinate columns both tables have.
  double extent = 0, mismatch = 0;
  for (const char* c : {"x", "y", "z"}) {
    std::size_t a = 0, b = 0;
    try {
      a = ref.column(c);
      b = test.column(c);
    } catch (const std::out_of_range&) {
      continue;
    }
    for (std::size_t i = 0; i < ref.rows.size(); ++i) {
      extent = std::max(extent, std::abs(ref.rows[i][a]));
      mismatch = std::max(mismatch, std::abs(ref.rows[i][a] - test.rows[i][b]));
    }
  }
  if (mismatch > 1e-6 * std::max(extent, 1e-30))
    throw std::invalid_argument("the probes do not sample the same points");

  std::vector<ComponentComparison> out;
  for (std::size_t k = 0; k < ref.columns.size(); ++k) {
    if (!is_field_component(ref.columns[k]))
      continue;
    std::size_t kt = 0;
    try {
      kt = test.column(ref.columns[k]);
    } catch (const std::out_of_range&) {
      continue;
    }
    ComponentComparison c;
    c.component = ref.columns[k];
    double sr = 0, st = 0, sd = 0;
    for (std::size_t i = 0; i < ref.rows.size(); ++i) {
      const double r = ref.rows[i][k], t = test.rows[i][kt];
      sr += r * r;
      st += t * t;
      sd += (t - r) * (t - r);
      c.max_abs_difference = std::max(c.max_abs_difference, std::abs(t - r));
    }
    const double n = static_cast<double>(ref.rows.size());
    c.rms_reference = std::sqrt(sr / n);
    c.rms_test = std::sqrt(st / n);
    c.rms_difference = std::sqrt(sd / n);
    out.push_back(c);
  }
  double largest = 0;
  for (const auto& c : out)
    largest = std::max(largest, c.rms_reference);
  for (auto& c : out) {
    c.relative_defined = c.rms_reference > 0 && c.rms_reference > 1e-9 * largest;
    if (c.relative_defined) {
      c.discrepancy_3117 = (c.rms_reference - c.rms_test) / c.rms_reference;
      c.pointwise_rms = c.rms_difference / c.rms_reference;
    }
  }
  return out;
}

} // namespace magfem
