#include "analytic/surface_patch_order.hpp"

#include <algorithm>
#include <cmath>

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

// Semi-major axis (rho + 1/rho) / 2 of the ellipse with foci -1, 1 through x + i y: half the
// sum of the distances to the foci.
double ellipse_semi_major(double x, double y) {
  return 0.5 * (std::sqrt((x - 1) * (x - 1) + y * y) + std::sqrt((x + 1) * (x + 1) + y * y));
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
  const double a = ellipse_semi_major(x, y);
  return a + std::sqrt(std::max(0.0, a * a - 1));
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
  double semi_major = 1e300; // of the Bernstein ellipse: the cosh(ln rho) that is returned
  for (int k = 0; k < 2; ++k) {
    const int j = 1 - k;
    const double offset = interval_gap(lo[k], hi[k], 0);
    const double side = interval_gap(lo[j], hi[j], a.half[j]);
    const double across = std::sqrt(normal_gap * normal_gap + side * side);
    const double distance = std::sqrt(offset * offset + across * across);
    if (margin > max_margin_fraction * distance)
      return std::nullopt;
    const double x = std::max(0.0, offset - margin) / a.half[k];
    const double y = std::max(0.0, across - margin) / a.half[k];
    semi_major = std::min(semi_major, ellipse_semi_major(x, y));
  }
  return semi_major;
}

} // namespace magfem
