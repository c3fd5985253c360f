#pragma once
// Accuracy settings of the coil source field (sources/coil_field.hpp). The defaults meet a
// relative error of 1e-6 away from the bundles and 1e-4 inside or next to them with a margin
// (measured in tests/sources and by magfem_bench_coil_field: ~1e-8 beyond a centimetre,
// ~1e-6 within it, ~2e-6 inside).
#include <stdexcept>

namespace magfem {

struct CoilFieldOptions {
  // Relative error aimed at by the zonal expansions and by the distance-adapted Gauss rules.
  double tolerance = 1e-8;
  // Gauss points per panel and direction of the split + Duffy rules used inside and next to a
  // bundle (relative error ~2e-6 at 6, ~1e-5 at 5, ~3e-5 at 4; tests/sources).
  int near_order = 6;
  // Largest number of points per direction of the far (tensor Gauss) rules; closer points
  // switch to the near rules.
  int far_order_max = 16;
  // Zonal harmonic expansions of axisymmetric coils where they converge (off: always
  // integrate the bundle, the independent reference the tests compare against).
  bool use_expansions = true;
  int expansion_terms = 160;
};

// Throws std::invalid_argument unless 0 < tolerance < 1, 2 <= near_order <= 32,
// 2 <= far_order_max <= 63 (the cached Gauss rules) and 2 <= expansion_terms <= 2000.
inline void check_options(const CoilFieldOptions& o) {
  if (!(o.tolerance > 0 && o.tolerance < 1) || o.near_order < 2 || o.near_order > 32 ||
      o.far_order_max < 2 || o.far_order_max > 63 || o.expansion_terms < 2 ||
      o.expansion_terms > 2000) {
    throw std::invalid_argument("CoilFieldOptions: tolerance in (0, 1), near_order in [2, 32], "
                                "far_order_max in [2, 63], expansion_terms in [2, 2000]");
  }
}

} // namespace magfem
