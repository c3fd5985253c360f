#include "validation/surface_patch_order.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

// Tangents further from orthogonal than this are not modelled (all our parameterizations
// are orthogonal; this only guards against degenerate boxes, e.g. at a pole).
constexpr double max_tangent_cosine = 1e-2;
// Margin factor on A's own sag (header comment) and the largest margin trusted, relative to
// the singularity's distance.
constexpr double own_sag_factor = 8;
constexpr double max_margin_fraction = 0.25;

// Distance between the intervals [lo, hi] and [-h, h].
double interval_gap(double lo, double hi, double h) {
  return std::max({0.0, lo - h, -h - hi});
}

} // namespace

SurfacePatch surface_patch(const ChargeDomain& d, const ParamBox& sub) {
  if (d.dim != 2)
    return {};
  std::array<Vec3, 9> grid;
  box_extent(d, sub, &grid);
  return surface_patch(grid);
}

SurfacePatch surface_patch(const std::array<Vec3, 9>& grid) {
  SurfacePatch p;
  p.samples = grid;
  const auto at = [&](int i, int j) -> const Vec3& { return p.samples[3 * i + j]; };
  p.centre = at(1, 1);
  const Vec3 e0 = 0.5 * (at(2, 1) - at(0, 1)), e1 = 0.5 * (at(1, 2) - at(1, 0));
  p.half = {e0.norm(), e1.norm()};
  if (!(p.half[0] > 0 && p.half[1] > 0))
    return p;
  p.tangent = {e0 / p.half[0], e1 / p.half[1]};
  if (std::abs(p.tangent[0].dot(p.tangent[1])) > max_tangent_cosine)
    return p;
  p.normal = p.tangent[0].cross(p.tangent[1]).normalized();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 model = p.centre + (i - 1) * e0 + (j - 1) * e1;
      p.sag = std::max(p.sag, (at(i, j) - model).norm());
    }
  p.valid = true;
  return p;
}

double bernstein_parameter(double x, double y) {
  // z + sqrt(z - 1) sqrt(z + 1) is the branch that maps the plane cut along [-1, 1] outside
  // the unit circle; the max guards the cut itself.
  const std::complex<double> z(x, y);
  const double r = std::abs(z + std::sqrt(z - 1.0) * std::sqrt(z + 1.0));
  return std::max(r, 1 / r);
}

std::optional<double> patch_pair_rho(const SurfacePatch& a, const SurfacePatch& b) {
  if (!a.valid || !b.valid)
    return std::nullopt;
  // b's samples in a's frame: intervals of the offsets along t_0, t_1 and n.
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Vec3& y : b.samples) {
    const Vec3 r = y - a.centre;
    const std::array<double, 3> c{r.dot(a.tangent[0]), r.dot(a.tangent[1]), r.dot(a.normal)};
    for (int k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
  }
  const double margin = own_sag_factor * a.sag + b.sag;
  const double normal_gap = interval_gap(lo[2], hi[2], 0);
  double rho = 1e300;
  for (int k = 0; k < 2; ++k) {
    const int j = 1 - k;
    const double offset = interval_gap(lo[k], hi[k], 0);
    const double across = std::hypot(normal_gap, interval_gap(lo[j], hi[j], a.half[j]));
    const double distance = std::hypot(offset, across);
    if (margin > max_margin_fraction * distance)
      return std::nullopt;
    const double x = std::max(0.0, offset - margin) / a.half[k];
    const double y = std::max(0.0, across - margin) / a.half[k];
    rho = std::min(rho, bernstein_parameter(x, y));
  }
  return 0.5 * (rho + 1 / rho);
}

} // namespace magfem
