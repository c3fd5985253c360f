#include "postproc/section_flux2d.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "mesh/mesh2d.hpp"

namespace magfem {
namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The part [lo, hi] of the segment s(u) = a + u (b - a), u in [0, 1], inside the straight
// triangle (counter-clockwise vertices); false when it misses or touches it in a point.
// `on_edge` says the piece lies along one of the triangle's edges.
bool clip_to_triangle(const std::array<Vec2, 3>& v, const Vec2& a, const Vec2& b, double& lo,
                      double& hi, bool& on_edge) {
  lo = 0, hi = 1, on_edge = false;
  const double scale = (b - a).norm() * (v[1] - v[0]).norm();
  for (int i = 0; i < 3; ++i) {
    const Vec2 e = v[(i + 1) % 3] - v[i];
    // Inside is to the left of each edge: f(u) = f0 + u (f1 - f0) >= 0.
    const double f0 = cross(e, a - v[i]), f1 = cross(e, b - v[i]);
    const double tol = 1e-12 * scale;
    if (std::abs(f0) <= tol && std::abs(f1) <= tol) {
      on_edge = true;
      continue;
    }
    if (f0 < 0 && f1 < 0)
      return false;
    if (f0 < 0)
      lo = std::max(lo, f0 / (f0 - f1));
    else if (f1 < 0)
      hi = std::min(hi, f0 / (f0 - f1));
  }
  return hi - lo > 1e-12;
}

std::array<double, 3> barycentric(const std::array<Vec2, 3>& v, const Vec2& x) {
  const double area2 = cross(v[1] - v[0], v[2] - v[0]);
  const double l1 = cross(x - v[0], v[2] - v[0]) / area2;
  const double l2 = cross(v[1] - v[0], x - v[0]) / area2;
  return {1 - l1 - l2, l1, l2};
}

// 4-point Gauss-Legendre on [0, 1].
constexpr std::array<double, 4> gauss_u = {0.0694318442029737, 0.3300094782075719,
                                           0.6699905217924281, 0.9305681557970263};
constexpr std::array<double, 4> gauss_w = {0.1739274225687269, 0.3260725774312731,
                                           0.3260725774312731, 0.1739274225687269};

} // namespace

SectionFlux integrate_section_2d(const Field2D& field, const SectionSpec& section, double depth) {
  const auto& problem = field.problem();
  const auto& mesh = *problem.mesh;
  const bool axi = problem.axisymmetric();
  const Vec2 a = section.start, b = section.end;
  const double length = (b - a).norm();
  const Vec2 t = (b - a) / length;
  const Vec2 n(-t.y(), t.x()); // z x t
  // The weight of a point of the line: the depth (planar) or the circumference 2 pi r.
  auto weight = [&](const Vec2& x) { return axi ? 2 * std::numbers::pi * x.x() : depth; };

  SectionFlux out;
  out.name = section.name;
  out.nominal_area_m2 = axi ? std::numbers::pi * (a.x() + b.x()) * length : depth * length;
  std::map<int, SectionPart> parts;
  for (std::size_t k = 0; k < mesh.n_triangles(); ++k) {
    if (mesh.triangle_part[k] == region_shell)
      continue; // outside the physical domain: counted as outside_area_m2
    const auto& tri = mesh.triangles[k];
    const std::array<Vec2, 3> v = {mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]};
    double lo = 0, hi = 0;
    bool on_edge = false;
    if (!clip_to_triangle(v, a, b, lo, hi, on_edge))
      continue;
    // Along an edge both neighbours clip the same piece: the one on the +n side counts it.
    if (on_edge && (v[0] + v[1] + v[2] - 3 * a).dot(n) < 0)
      continue;
    SectionPart& part = parts[mesh.triangle_part[k]];
    part.region = mesh.triangle_part[k];
    const double piece = (hi - lo) * length;
    for (std::size_t q = 0; q < gauss_u.size(); ++q) {
      const Vec2 x = a + (lo + gauss_u[q] * (hi - lo)) * (b - a);
      const Vec2 bq = field.B(k, barycentric(v, x));
      const double w = gauss_w[q] * piece * weight(x);
      part.area_m2 += w;
      part.flux_Wb += w * bq.dot(n);
      part.abs_B_Tm2 += w * bq.norm();
    }
  }
  finish_section_2d(out, parts);
  return out;
}

void finish_section_2d(SectionFlux& out, const std::map<int, SectionPart>& parts) {
  for (const auto& [region, p] : parts) {
    out.parts.push_back(p);
    out.total.area_m2 += p.area_m2;
    out.total.flux_Wb += p.flux_Wb;
    out.total.abs_B_Tm2 += p.abs_B_Tm2;
  }
  out.outside_area_m2 = std::max(0.0, out.nominal_area_m2 - out.total.area_m2);
}

} // namespace magfem
