#include "pipeline/memory_guard.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "core/input_error.hpp"

namespace magfem {
namespace {

// Calibrated (docs/performance.md, "Memory guard calibration"): MB, and kB per tetrahedron by order, fitted to the
// measured peaks of the 3D examples (order 2: DOF map, matrix and the incomplete-Cholesky
// or CHOLMOD factor dominate; order 1: TetGen's structures and the mesh).
constexpr double base_mb = 50;
constexpr double kb_per_tet_order1 = 0.36;
constexpr double kb_per_tet_order2 = 2.2;
constexpr double kb_per_tet_coil = 0.25;

double meminfo_available_mb() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:")
      return kb / 1024;
  return std::numeric_limits<double>::infinity();
}

// cgroup v2: the limit of this process's group minus what the group uses ("max" = none).
double cgroup_available_mb() {
  std::ifstream limit("/sys/fs/cgroup/memory.max"), used("/sys/fs/cgroup/memory.current");
  std::string max_text;
  double current = 0;
  if (!(limit >> max_text) || max_text == "max" || !(used >> current))
    return std::numeric_limits<double>::infinity();
  try {
    return (std::stod(max_text) - current) / (1024 * 1024);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::infinity();
  }
}

double kb_per_tet(int order) {
  return order == 2 ? kb_per_tet_order2 : kb_per_tet_order1;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

} // namespace

double estimated_peak_memory_mb(double tetrahedra, int order, int n_coils) {
  // The coils: the source-field table at the rule and DOF points (0.18 kB per tetrahedron and
  // coil, single precision), the source potentials and the memo of the other points; measured
  // 0.25 kB in all (order 2, 12 coils, 423k tetrahedra: 2.23 GB peak against 0.99 GB without
  // coils). Order 1 is given the same (the table has the same rule: the same size).
  const double coil_cache_mb = tetrahedra * n_coils * kb_per_tet_coil / 1024;
  return base_mb + tetrahedra * kb_per_tet(order) / 1024 + coil_cache_mb;
}

double memory_limit_mb(double max_memory_gb) {
  if (max_memory_gb > 0)
    return 1024 * max_memory_gb;
  return std::min(meminfo_available_mb(), cgroup_available_mb());
}

double MemoryLimit::share_mb() const {
  return (shared_mb > 0 ? shared_mb : memory_limit_mb(max_memory_gb)) / std::max(1, parallel_runs);
}

void check_memory(const MeshEstimate3D& estimate, int order, int n_coils, const MemoryLimit& memory,
                  double mesh_scale, const std::function<double(double)>& tets_at_factor) {
  const double limit = memory.share_mb();
  const double need = estimated_peak_memory_mb(estimate.tetrahedra, order, n_coils);
  if (need <= limit)
    return;
  const bool given = memory.max_memory_gb > 0;
  const std::string field = given ? "--max-memory" : "--mesh-scale";
  std::string source = given ? "the --max-memory limit" : "the memory available now";
  if (memory.parallel_runs > 1)
    source = "its 1/" + std::to_string(memory.parallel_runs) + " share of " + source + " (" +
             std::to_string(memory.parallel_runs) + " runs at once, --jobs)";
  std::string message = "the mesh would have about " + fixed(estimate.tetrahedra / 1e6, 2) +
                        " million tetrahedra and need about " + fixed(need / 1024, 2) +
                        " GB at order " + std::to_string(order) + ", more than " + source + " (" +
                        fixed(limit / 1024, 2) + " GB); ";
  // The smallest factor 1.25^k (k = 1..9, up to 7.45) whose estimate fits with a 30 %
  // margin (the estimate's spread over the calibration runs), by bisection: each estimate
  // rebuilds the size field (seconds on large cases), and the count falls as the factor
  // grows. The answer is rounded up to two significant digits.
  constexpr int n_factors = 9;
  constexpr double step = 1.25;
  const double max_factor = std::pow(step, n_factors);
  const auto fits = [&](int k, double& tets) {
    tets = tets_at_factor(std::pow(step, k));
    return 1.3 * estimated_peak_memory_mb(tets, order, n_coils) <= limit;
  };
  double tets = 0;
  if (1.3 * base_mb < limit && fits(n_factors, tets)) {
    int lo = 0, hi = n_factors; // lo does not fit (the present mesh), hi does
    double tets_hi = tets;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      if (fits(mid, tets))
        hi = mid, tets_hi = tets;
      else
        lo = mid;
    }
    double s = mesh_scale * std::pow(step, hi);
    const double mag = std::pow(10.0, std::floor(std::log10(s)) - 1);
    s = std::ceil(s / mag - 1e-9) * mag;
    message += "--mesh-scale " + fixed(s, s < 10 ? 2 : 1) + " would fit (about " +
               fixed(tets_hi / 1e6, 2) + " million tetrahedra)";
    throw InputError("<command line>", 0, field, message);
  }
  message += "no --mesh-scale up to " + fixed(max_factor * mesh_scale, 1) +
             " fits: the curved surfaces' chord_tolerance bounds the element size (it does "
             "not grow with --mesh-scale; raise it in the case file), or the limit is below "
             "the " +
             fixed(base_mb, 0) + " MB a run needs before any element";
  throw InputError("<command line>", 0, field, message);
}

} // namespace magfem
