#include "postproc/section_flux3d.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Dense>

#include "core/constants.hpp"
#include "postproc/tet_plane_cut.hpp"
#include "solver/triangle_quadrature.hpp"

namespace magfem {

namespace {

using Polygon = TetPlaneCut;

constexpr int disk_sides = 256; // see section_flux3d.hpp for the error this leaves

// The half-planes a.p <= b whose intersection is the section's outline in (u, v).
struct HalfPlane {
  Eigen::Vector2d a;
  double b;
};

std::vector<HalfPlane> outline(const SectionSpec& s) {
  if (s.kind == SectionSpec::Kind::rectangle)
    return {{{1, 0}, s.size_u / 2},
            {{-1, 0}, s.size_u / 2},
            {{0, 1}, s.size_v / 2},
            {{0, -1}, s.size_v / 2}};
  // Equal-area regular polygon: N/2 R^2 sin(2 pi / N) = pi r^2.
  const double step = 2 * pi / disk_sides;
  const double circumradius = s.radius * std::sqrt(2 * pi / (disk_sides * std::sin(step)));
  const double apothem = circumradius * std::cos(step / 2);
  std::vector<HalfPlane> out;
  for (int k = 0; k < disk_sides; ++k) {
    const double angle = (k + 0.5) * step;
    out.push_back({{std::cos(angle), std::sin(angle)}, apothem});
  }
  return out;
}

// Sutherland-Hodgman: the part of convex polygon p with a.x <= b.
Polygon clip(const Polygon& p, const HalfPlane& h) {
  Polygon out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d &x = p[i], &y = p[(i + 1) % p.size()];
    const double dx = h.a.dot(x) - h.b, dy = h.a.dot(y) - h.b;
    if (dx <= 0)
      out.push_back(x);
    if ((dx < 0 && dy > 0) || (dx > 0 && dy < 0))
      out.push_back(x + dx / (dx - dy) * (y - x));
  }
  return out;
}

Polygon clip_to_outline(Polygon p, const std::vector<HalfPlane>& planes) {
  bool inside = true;
  for (const auto& h : planes) {
    double lo = h.a.dot(p[0]) - h.b, hi = lo;
    for (const auto& x : p) {
      lo = std::min(lo, h.a.dot(x) - h.b);
      hi = std::max(hi, h.a.dot(x) - h.b);
    }
    if (lo >= 0)
      return {}; // wholly outside this side
    inside = inside && hi <= 0;
  }
  if (inside)
    return p;
  for (const auto& h : planes) {
    p = clip(p, h);
    if (p.size() < 3)
      return {};
  }
  return p;
}

void add(SectionPart& to, const SectionPart& from) {
  to.area_m2 += from.area_m2;
  to.flux_Wb += from.flux_Wb;
  to.abs_B_Tm2 += from.abs_B_Tm2;
}

// The integrals of polygon p (in the plane's coordinates) inside tet t, whose straight
// vertices are x.
SectionPart integrate_polygon(const Field3D& field, std::size_t t,
                              const std::array<Eigen::Vector3d, 4>& x, const Polygon& p,
                              const PlaneFrame& f) {
  Eigen::Matrix3d jac;
  jac << x[1] - x[0], x[2] - x[0], x[3] - x[0];
  const Eigen::Matrix3d inv = jac.inverse();
  SectionPart out;
  const auto& rule = triangle_rule(4);
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    const Eigen::Vector2d e1 = p[k] - p[0], e2 = p[k + 1] - p[0];
    const double area = 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
    if (area == 0)
      continue;
    for (const auto& q : rule) {
      const Eigen::Vector2d y = q.bary[0] * p[0] + q.bary[1] * p[k] + q.bary[2] * p[k + 1];
      const Eigen::Vector3d l = inv * (f.at(y.x(), y.y()) - x[0]);
      const Eigen::Vector3d b = field.B(t, {1 - l.sum(), l.x(), l.y(), l.z()});
      const double w = q.weight * area;
      out.area_m2 += w;
      out.flux_Wb += w * b.dot(f.n);
      out.abs_B_Tm2 += w * b.norm();
    }
  }
  return out;
}

} // namespace

SectionFlux integrate_section_3d(const Field3D& field, const SectionSpec& section) {
  const Mesh3D& mesh = *field.problem().mesh;
  const std::vector<HalfPlane> planes = outline(section);
  std::map<int, SectionPart> parts;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    std::array<Eigen::Vector3d, 4> x;
    for (int i = 0; i < 4; ++i)
      x[i] = mesh.nodes[mesh.tets[t][i]];
    const Polygon cut = cut_tet_by_plane(x, section.frame);
    if (cut.size() < 3)
      continue;
    const Polygon p = clip_to_outline(cut, planes);
    if (p.size() < 3)
      continue;
    const int region = mesh.tet_part[t];
    if (region == region_shell_3d)
      continue; // mapped exterior: not physical space (counted in outside_area_m2)
    SectionPart& part = parts[region];
    part.region = region;
    add(part, integrate_polygon(field, t, x, p, section.frame));
  }
  SectionFlux out;
  out.name = section.name;
  out.nominal_area_m2 = section.area();
  for (const auto& [region, part] : parts) {
    out.parts.push_back(part);
    add(out.total, part);
  }
  out.outside_area_m2 = std::max(0.0, out.nominal_area_m2 - out.total.area_m2);
  return out;
}

} // namespace magfem
