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

// Calibrated (docs/performance.md, "Memory guard calibration"): MB, and kB per tetrahedron by
// order, fitted to the measured peaks of the 3D examples (order 2: DOF map, matrix and the
// incomplete-Cholesky or CHOLMOD factor dominate; order 1: TetGen's structures and the mesh).
constexpr double base_mb = 50;
constexpr double kb_per_tet_order1 = 0.36;
constexpr double kb_per_tet_order2 = 2.2;
constexpr double kb_per_tet_coil = 0.25;
// Planar and axisymmetric (docs/performance.md, the same section): a smaller base (no TetGen,
// no size-field octree) and kB per triangle and decade of the triangle count, by order: the
// nested-dissection factor of a 2D mesh grows as n log n (fitted to 14 runs, 6k to 425k
// triangles: within -7..+6 % at order 1, -5..+22 % at order 2).
constexpr double base_mb_2d = 25;
constexpr double kb_per_triangle_decade_order1 = 0.092;
constexpr double kb_per_triangle_decade_order2 = 0.43;

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

namespace {

// The guard of either dimension: `elements` (what the mesh has or would have) cost
// `peak_mb(n)`; `elements_at_factor(f)` is the count with every size multiplied by f; `hint`
// says why no --mesh-scale may fit.
void check_elements(double elements, const std::string& element_name, int order, double base,
                    const std::function<double(double)>& peak_mb, const MemoryLimit& memory,
                    double mesh_scale, const std::function<double(double)>& elements_at_factor,
                    const std::string& hint) {
  const double limit = memory.share_mb();
  const double need = peak_mb(elements);
  if (need <= limit)
    return;
  const bool given = memory.max_memory_gb > 0;
  const std::string field = given ? "--max-memory" : "--mesh-scale";
  std::string source = given ? "the --max-memory limit" : "the memory available now";
  if (memory.parallel_runs > 1)
    source = "its 1/" + std::to_string(memory.parallel_runs) + " share of " + source + " (" +
             std::to_string(memory.parallel_runs) + " runs at once, --jobs)";
  std::string message = "the mesh would have about " + fixed(elements / 1e6, 2) + " million " +
                        element_name + " and need about " + fixed(need / 1024, 2) +
                        " GB at order " + std::to_string(order) + ", more than " + source + " (" +
                        fixed(limit / 1024, 2) + " GB); ";
  // The smallest factor 1.25^k (k = 1..9, up to 7.45) whose estimate fits with a 30 %
  // margin (the estimate's spread over the calibration runs), by bisection: each estimate
  // rebuilds the size field (seconds on large 3D cases), and the count falls as the factor
  // grows. The answer is rounded up to two significant digits.
  constexpr int n_factors = 9;
  constexpr double step = 1.25;
  const double max_factor = std::pow(step, n_factors);
  const auto fits = [&](int k, double& n) {
    n = elements_at_factor(std::pow(step, k));
    return 1.3 * peak_mb(n) <= limit;
  };
  double n = 0;
  if (1.3 * base < limit && fits(n_factors, n)) {
    int lo = 0, hi = n_factors; // lo does not fit (the present mesh), hi does
    double n_hi = n;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      if (fits(mid, n))
        hi = mid, n_hi = n;
      else
        lo = mid;
    }
    double s = mesh_scale * std::pow(step, hi);
    const double mag = std::pow(10.0, std::floor(std::log10(s)) - 1);
    s = std::ceil(s / mag - 1e-9) * mag;
    message += "--mesh-scale " + fixed(s, s < 10 ? 2 : 1) + " would fit (about " +
               fixed(n_hi / 1e6, 2) + " million " + element_name + ")";
    throw InputError("<command line>", 0, field, message);
  }
  message += "no --mesh-scale up to " + fixed(max_factor * mesh_scale, 1) + " fits: " + hint +
             "the limit is below the " + fixed(base, 0) + " MB a run needs before any element";
  throw InputError("<command line>", 0, field, message);
}

} // namespace

void check_memory(const MeshEstimate3D& estimate, int order, int n_coils, const MemoryLimit& memory,
                  double mesh_scale, const std::function<double(double)>& tets_at_factor) {
  check_elements(
      estimate.tetrahedra, "tetrahedra", order, base_mb,
      [&](double tets) { return estimated_peak_memory_mb(tets, order, n_coils); }, memory,
      mesh_scale, tets_at_factor,
      "the curved surfaces' chord_tolerance bounds the element size (it does not grow with "
      "--mesh-scale; raise it in the case file), or ");
}

double estimated_peak_memory_mb_2d(double triangles, int order) {
  const double per_decade =
      order == 2 ? kb_per_triangle_decade_order2 : kb_per_triangle_decade_order1;
  return base_mb_2d + triangles * per_decade * std::log10(std::max(triangles, 10.0)) / 1024;
}

void check_memory_2d(double triangles, int order, const MemoryLimit& memory, double mesh_scale) {
  // A 2D mesher's triangle count goes as the area over the size squared: with every size
  // multiplied by f, about n / f^2 (the boundary's arcs coarsen less; the 30 % margin and
  // the guard at the proposed scale's own mesh catch the rest).
  check_elements(
      triangles, "triangles", order, base_mb_2d,
      [&](double n) { return estimated_peak_memory_mb_2d(n, order); }, memory, mesh_scale,
      [&](double f) { return triangles / (f * f); }, "");
}

} // namespace magfem
