#include "tests/fuzz/fuzz_entries.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "casefile/case_spec.hpp"
#include "core/input_error.hpp"
#include "core/yaml_node.hpp"
#include "materials/material_library.hpp"
#include "materials/material_parser.hpp"
#include "postproc/probe_compare.hpp"

namespace magfem::fuzz {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::logic_error("fuzz invariant violated: " + what);
}

// B(H) from the curve is what the 2D and 3D Newton loops evaluate, anywhere from 0 to well
// past the table; its inverse must come back (relative 1e-6: the inversion is iterative).
void check_curve(const BhCurve& c) {
  const auto& h = c.h_table();
  std::vector<double> at = {0.0};
  for (std::size_t k = 0; k < h.size(); ++k) {
    at.push_back(h[k]);
    if (k + 1 < h.size())
      at.push_back(0.5 * (h[k] + h[k + 1]));
  }
  if (h.back() < 1e300)
    at.push_back(2 * h.back());
  for (const double x : at) {
    const double b = c.b_of_h(x), d = c.dbdh(x);
    require(std::isfinite(b) && std::isfinite(d), "B(H) finite at H = " + std::to_string(x));
    require(c.b_of_h(-x) == -b, "B(H) odd");
    const double back = c.h_of_b(b);
    require(std::abs(back - x) <= 1e-6 * std::max(x, h[1]), "H(B(H)) = H");
    double nu = 0, dnu = 0;
    c.nu_of_b2(b * b, nu, dnu);
    require(std::isfinite(nu) && std::isfinite(dnu), "nu(B^2) finite");
  }
}

} // namespace

void case_reader(std::string_view data) {
  try {
    read_case_text(std::string(data), "fuzz.yaml");
  } catch (const InputError&) {
  }
}

void material_parser(std::string_view data) {
  try {
    const auto root = YamlNode::load_string(std::string(data), "fuzz.yaml");
    if (root.is_map() && root.has("materials")) {
      const auto lib = MaterialLibrary::from_yaml(root);
      for (const auto& name : lib.names())
        if (const auto* m = lib.find(name); m && m->curve)
          check_curve(*m->curve);
      parse_materials(root.at("materials"), MaterialLibrary::bundled());
    } else {
      check_curve(*parse_bh_table(root));
    }
  } catch (const InputError&) {
  }
}

void probe_csv(std::string_view data) {
  try {
    std::istringstream in{std::string(data)};
    const auto table = read_probe_csv(in, "fuzz.csv");
    for (const auto& row : table.rows) {
      require(row.size() == table.columns.size(), "rows as wide as the header");
      for (const double v : row)
        require(std::isfinite(v), "values finite (compare's rms would be NaN)");
    }
    for (const auto& c : compare_probes(table, table))
      require(!(c.max_abs_difference > 0), "a table compared with itself differs");
  } catch (const InputError&) {
  } catch (const std::invalid_argument&) {
    // compare_probes' documented refusal (different points); run_compare turns it into an
    // InputError.
  }
}

} // namespace magfem::fuzz
