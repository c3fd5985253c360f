#include "analytic/charge_source.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

// Parameter value with its sine and cosine (angles are the common case; computing them once
// per 1D node instead of once per tensor node keeps on-the-fly patches cheap).
struct Node {
  double u, s, c;
};

Node make_node(double u) {
  return {u, std::sin(u), std::cos(u)};
}

// Local position and area vector (surface, |dA| = Jacobian) or volume Jacobian.
struct LocalGeometry {
  Vec3 p;
  Vec3 dA; // surfaces only
  double dV = 0;
};

LocalGeometry local_geometry(const ChargeDomain& d, const Node& a, const Node& b, const Node& c,
                             double sf, double cf) {
  LocalGeometry g;
  switch (d.kind) {
  case ChargeDomainKind::sphere_face: { // theta = a, phi = b
    const Vec3 rh(a.s * b.c, a.s * b.s, a.c);
    g.p = d.fixed * rh;
    g.dA = d.orient * d.fixed * d.fixed * a.s * rh;
    break;
  }
  case ChargeDomainKind::cone_face: { // rho = a, phi = b, theta fixed (sf, cf)
    const Vec3 rh(sf * b.c, sf * b.s, cf);
    const Vec3 et(cf * b.c, cf * b.s, -sf);
    g.p = a.u * rh;
    g.dA = d.orient * a.u * sf * et;
    break;
  }
  case ChargeDomainKind::meridian_face: { // rho = a, theta = b, phi fixed (sf, cf)
    g.p = a.u * Vec3(b.s * cf, b.s * sf, b.c);
    g.dA = d.orient * a.u * Vec3(-sf, cf, 0);
    break;
  }
  case ChargeDomainKind::sphere_volume: // rho = a, theta = b, phi = c
    g.p = a.u * Vec3(b.s * c.c, b.s * c.s, b.c);
    g.dV = a.u * a.u * b.s;
    break;
  case ChargeDomainKind::cap_face: // r = a, alpha = b
    g.p = Vec3(a.u * b.c, a.u * b.s, d.fixed);
    g.dA = Vec3(0, 0, d.orient * a.u);
    break;
  case ChargeDomainKind::mantle_face: // alpha = a, z = b
    g.p = Vec3(d.fixed * a.c, d.fixed * a.s, b.u);
    g.dA = d.orient * d.fixed * Vec3(a.c, a.s, 0);
    break;
  case ChargeDomainKind::cylinder_volume: // r = a, alpha = b, z = c
    g.p = Vec3(a.u * b.c, a.u * b.s, c.u);
    g.dV = a.u;
    break;
  case ChargeDomainKind::box_face:
    g.p[d.axis] = d.fixed;
    g.p[(d.axis + 1) % 3] = a.u;
    g.p[(d.axis + 2) % 3] = b.u;
    g.dA = Vec3::Zero();
    g.dA[d.axis] = d.orient;
    break;
  case ChargeDomainKind::box_volume:
    g.p = Vec3(a.u, b.u, c.u);
    g.dV = 1;
    break;
  }
  return g;
}

// -div M at global x: zero for parallel, -2 M0 sign / |x - c| for radial (div of f(r) e_r is
// (1/r^2) d(r^2 f)/dr = 2 f / r for constant f).
double volume_density(const ChargeDomain& d, const Vec3& x) {
  if (d.magnetization.pattern != Magnetization::Pattern::radial)
    return 0;
  const double r = (x - d.magnetization.center).norm();
  return r > 0 ? -2.0 * d.M0 * d.magnetization.sign / r : 0;
}

// True if M.n (charge) or M x n (current) is nonzero somewhere on the face.
bool face_is_loaded(const ChargeDomain& d, bool current) {
  const int n = 5;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = d.box.lo[0] + (d.box.hi[0] - d.box.lo[0]) * (i + 0.5) / n;
      const double v = d.box.lo[1] + (d.box.hi[1] - d.box.lo[1]) * (j + 0.5) / n;
      const LocalGeometry g = local_geometry(d, make_node(u), make_node(v), make_node(0),
                                             std::sin(d.fixed), std::cos(d.fixed));
      const double a = g.dA.norm();
      if (a == 0)
        continue;
      const Vec3 x = d.placement.to_global(g.p);
      const Vec3 n_hat = d.placement.rotation * g.dA / a;
      const Vec3 u_m = d.magnetization.unit_at(x);
      const double load = current ? u_m.cross(n_hat).norm() : std::abs(u_m.dot(n_hat));
      if (load > 1e-12)
        return true;
    }
  return false;
}

ChargeDomain make_domain(const AnalyticMagnet& m, ChargeDomainKind kind, double fixed,
                         double orient, ParamBox box, int dim, int axis = 0) {
  ChargeDomain d;
  d.kind = kind;
  d.fixed = fixed;
  d.orient = orient;
  d.axis = axis;
  d.dim = dim;
  d.box = box;
  d.placement = m.placement;
  d.magnetization = m.magnetization;
  d.M0 = m.B_r / mu0;
  return d;
}

void segment_domains(const AnalyticMagnet& m, const SphericalSegment& s,
                     std::vector<ChargeDomain>& out) {
  using K = ChargeDomainKind;
  const ParamBox tp{{s.theta_min, s.phi_min, 0}, {s.theta_max, s.phi_max, 0}};
  const ParamBox rp{{s.r_inner, s.phi_min, 0}, {s.r_outer, s.phi_max, 0}};
  const ParamBox rt{{s.r_inner, s.theta_min, 0}, {s.r_outer, s.theta_max, 0}};
  out.push_back(make_domain(m, K::sphere_face, s.r_outer, 1, tp, 2));
  if (s.r_inner > 0)
    out.push_back(make_domain(m, K::sphere_face, s.r_inner, -1, tp, 2));
  if (std::sin(s.theta_max) > 1e-12)
    out.push_back(make_domain(m, K::cone_face, s.theta_max, 1, rp, 2));
  if (std::sin(s.theta_min) > 1e-12)
    out.push_back(make_domain(m, K::cone_face, s.theta_min, -1, rp, 2));
  if (s.phi_max - s.phi_min < 2 * pi - 1e-12) {
    out.push_back(make_domain(m, K::meridian_face, s.phi_max, 1, rt, 2));
    out.push_back(make_domain(m, K::meridian_face, s.phi_min, -1, rt, 2));
  }
  out.push_back(make_domain(
      m, K::sphere_volume, 0, 1,
      ParamBox{{s.r_inner, s.theta_min, s.phi_min}, {s.r_outer, s.theta_max, s.phi_max}}, 3));
}

void cylinder_domains(const AnalyticMagnet& m, const Cylinder& c, std::vector<ChargeDomain>& out) {
  using K = ChargeDomainKind;
  const ParamBox ra{{c.r_inner, 0, 0}, {c.r_outer, 2 * pi, 0}};
  const ParamBox az{{0, 0, 0}, {2 * pi, c.height, 0}};
  out.push_back(make_domain(m, K::cap_face, c.height, 1, ra, 2));
  out.push_back(make_domain(m, K::cap_face, 0, -1, ra, 2));
  out.push_back(make_domain(m, K::mantle_face, c.r_outer, 1, az, 2));
  if (c.r_inner > 0)
    out.push_back(make_domain(m, K::mantle_face, c.r_inner, -1, az, 2));
  out.push_back(make_domain(m, K::cylinder_volume, 0, 1,
                            ParamBox{{c.r_inner, 0, 0}, {c.r_outer, 2 * pi, c.height}}, 3));
}

void box_domains(const AnalyticMagnet& m, const Box& b, std::vector<ChargeDomain>& out) {
  using K = ChargeDomainKind;
  const Vec3 h = b.size / 2;
  for (int a = 0; a < 3; ++a) {
    const int i = (a + 1) % 3, j = (a + 2) % 3;
    const ParamBox face{{-h[i], -h[j], 0}, {h[i], h[j], 0}};
    out.push_back(make_domain(m, K::box_face, h[a], 1, face, 2, a));
    out.push_back(make_domain(m, K::box_face, -h[a], -1, face, 2, a));
  }
  out.push_back(
      make_domain(m, K::box_volume, 0, 1, ParamBox{{-h[0], -h[1], -h[2]}, {h[0], h[1], h[2]}}, 3));
}

} // namespace

GaussRule::GaussRule(int n) {
  if (n < 1)
    throw std::invalid_argument("GaussRule: order must be >= 1");
  QuadratureRule rule = gauss_legendre(n);
  nodes = std::move(rule.x);
  weights = std::move(rule.w);
}

Vec3 ChargeDomain::point(const std::array<double, 3>& u) const {
  const LocalGeometry g = local_geometry(*this, make_node(u[0]), make_node(u[1]), make_node(u[2]),
                                         std::sin(fixed), std::cos(fixed));
  return placement.to_global(g.p);
}

void ChargeDomain::quadrature(const ParamBox& sub, const GaussRule& rule,
                              std::vector<PointCharge>& out) const {
  const int n = rule.size();
  std::array<std::vector<Node>, 3> nodes;
  std::array<std::vector<double>, 3> w;
  for (int a = 0; a < 3; ++a) {
    const bool used = a < dim;
    const int m = used ? n : 1;
    const double half = used ? 0.5 * (sub.hi[a] - sub.lo[a]) : 0;
    const double mid = 0.5 * (sub.hi[a] + sub.lo[a]);
    for (int i = 0; i < m; ++i) {
      nodes[a].push_back(make_node(used ? mid + half * rule.nodes[i] : mid));
      w[a].push_back(used ? half * rule.weights[i] : 1.0);
    }
  }
  const double sf = std::sin(fixed), cf = std::cos(fixed);
  const Mat3& R = placement.rotation;
  for (std::size_t i = 0; i < nodes[0].size(); ++i)
    for (std::size_t j = 0; j < nodes[1].size(); ++j)
      for (std::size_t k = 0; k < nodes[2].size(); ++k) {
        const LocalGeometry g =
            local_geometry(*this, nodes[0][i], nodes[1][j], nodes[2][k], sf, cf);
        const Vec3 x = placement.to_global(g.p);
        const double wt = w[0][i] * w[1][j] * w[2][k];
        double q;
        if (dim == 2)
          q = M0 * magnetization.unit_at(x).dot(R * g.dA) * wt;
        else
          q = volume_density(*this, x) * g.dV * wt;
        out.push_back({x, q});
      }
}

void check_shape(const AnalyticMagnet& magnet) {
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("magnet '" + magnet.name + "': " + what);
  };
  if (const auto* s = std::get_if<SphericalSegment>(&magnet.shape)) {
    if (!(s->r_inner >= 0 && s->r_outer > s->r_inner))
      fail("spherical segment needs 0 <= r_inner < r_outer");
    if (!(s->theta_min >= 0 && s->theta_max > s->theta_min && s->theta_max <= pi + 1e-12))
      fail("spherical segment needs 0 <= theta_min < theta_max <= pi");
    if (!(s->phi_max > s->phi_min && s->phi_max - s->phi_min <= 2 * pi + 1e-12))
      fail("spherical segment needs phi_min < phi_max <= phi_min + 2 pi");
  } else if (const auto* c = std::get_if<Cylinder>(&magnet.shape)) {
    if (!(c->r_inner >= 0 && c->r_outer > c->r_inner && c->height > 0))
      fail("cylinder needs 0 <= r_inner < r_outer and height > 0");
  } else if (const auto* b = std::get_if<Box>(&magnet.shape)) {
    if (!(b->size.minCoeff() > 0))
      fail("box needs positive sizes");
  } else {
    fail("the charge model takes spherical segments, cylinders and boxes, not triangulated "
         "surfaces");
  }
  if (magnet.magnetization.active() && !(magnet.B_r >= 0))
    fail("B_r must be >= 0");
  if (magnet.magnetization.pattern == Magnetization::Pattern::parallel &&
      std::abs(magnet.magnetization.direction.norm() - 1) > 1e-9)
    fail("parallel direction must be a unit vector");
}

void ChargeDomain::current_quadrature(const ParamBox& sub, const GaussRule& rule,
                                      std::vector<PointCurrent>& out) const {
  // The same tensor nodes as quadrature() (surfaces only).
  const int n = rule.size();
  std::array<std::vector<Node>, 2> nodes;
  std::array<std::vector<double>, 2> w;
  for (int a = 0; a < 2; ++a) {
    const double half = 0.5 * (sub.hi[a] - sub.lo[a]);
    const double mid = 0.5 * (sub.hi[a] + sub.lo[a]);
    for (int i = 0; i < n; ++i) {
      nodes[a].push_back(make_node(mid + half * rule.nodes[i]));
      w[a].push_back(half * rule.weights[i]);
    }
  }
  const double sf = std::sin(fixed), cf = std::cos(fixed);
  const Mat3& R = placement.rotation;
  const Node none = make_node(0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const LocalGeometry g = local_geometry(*this, nodes[0][i], nodes[1][j], none, sf, cf);
      const Vec3 x = placement.to_global(g.p);
      const Vec3 m = M0 * magnetization.unit_at(x);
      out.push_back({x, m.cross(R * g.dA) * (w[0][i] * w[1][j])});
    }
}

std::vector<ChargeDomain> charge_domains(const AnalyticMagnet& magnet) {
  check_shape(magnet);
  std::vector<ChargeDomain> all;
  if (const auto* s = std::get_if<SphericalSegment>(&magnet.shape))
    segment_domains(magnet, *s, all);
  else if (const auto* c = std::get_if<Cylinder>(&magnet.shape))
    cylinder_domains(magnet, *c, all);
  else if (const auto* b = std::get_if<Box>(&magnet.shape))
    box_domains(magnet, *b, all);
  std::vector<ChargeDomain> kept;
  for (const ChargeDomain& d : all) {
    if (d.dim == 3 && d.magnetization.pattern != Magnetization::Pattern::radial)
      continue; // div M = 0
    if (d.dim == 2 && !face_is_loaded(d, false))
      continue;
    kept.push_back(d);
  }
  return kept;
}

std::vector<ChargeDomain> current_domains(const AnalyticMagnet& magnet) {
  check_shape(magnet);
  std::vector<ChargeDomain> all;
  if (const auto* s = std::get_if<SphericalSegment>(&magnet.shape))
    segment_domains(magnet, *s, all);
  else if (const auto* c = std::get_if<Cylinder>(&magnet.shape))
    cylinder_domains(magnet, *c, all);
  else if (const auto* b = std::get_if<Box>(&magnet.shape))
    box_domains(magnet, *b, all);
  std::vector<ChargeDomain> kept;
  for (const ChargeDomain& d : all)
    if (d.dim == 2 && face_is_loaded(d, true))
      kept.push_back(d);
  return kept;
}

BoxExtent box_extent(const ChargeDomain& d, const ParamBox& sub, std::array<Vec3, 9>* grid) {
  // Sample the box on the 3^dim grid {lo, mid, hi}, in local coordinates (the placement is
  // rigid), with the sines and cosines computed once per axis value: this runs for every
  // box built on the fly in the near field.
  const int m = d.dim == 2 ? 1 : 3;
  Node nodes[3][3];
  for (int a = 0; a < 3; ++a)
    for (int t = 0; t < 3; ++t)
      nodes[a][t] = make_node(sub.lo[a] + 0.5 * t * (sub.hi[a] - sub.lo[a]));
  const double sf = std::sin(d.fixed), cf = std::cos(d.fixed);
  Vec3 pts[3][3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < m; ++k)
        pts[i][j][k] =
            local_geometry(d, nodes[0][i], nodes[1][j], nodes[2][d.dim == 2 ? 1 : k], sf, cf).p;
  if (grid && d.dim == 2)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        (*grid)[3 * i + j] = d.placement.to_global(pts[i][j][0]);
  BoxExtent e;
  const Vec3& centre = pts[1][1][d.dim == 2 ? 0 : 1];
  e.centre = d.placement.to_global(centre);
  double best = -1;
  for (int a = 0; a < d.dim; ++a) {
    double len = 0;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < m; ++q) {
        auto at = [&](int t) -> const Vec3& {
          if (a == 0)
            return pts[t][p][q];
          if (a == 1)
            return pts[p][t][q];
          return pts[p][q][t];
        };
        if (a == 2 && m == 1)
          continue;
        len = std::max(len, (at(1) - at(0)).norm() + (at(2) - at(1)).norm());
      }
    if (len > best) {
      best = len;
      e.longest_axis = a;
    }
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < m; ++k)
        e.radius = std::max(e.radius, (pts[i][j][k] - centre).norm());
  return e;
}

std::array<bool, 3> angular_parameters(const ChargeDomain& d) {
  using K = ChargeDomainKind;
  switch (d.kind) {
  case K::sphere_face:
    return {true, true, false};
  case K::cone_face:
  case K::meridian_face:
  case K::cap_face:
    return {false, true, false};
  case K::sphere_volume:
    return {false, true, true};
  case K::mantle_face:
    return {true, false, false};
  case K::cylinder_volume:
    return {false, true, false};
  case K::box_face:
  case K::box_volume:
    break;
  }
  return {false, false, false};
}

std::vector<ParamBox> root_boxes(const ChargeDomain& d, double max_angle) {
  const std::array<bool, 3> angular = angular_parameters(d);
  std::vector<ParamBox> boxes{d.box};
  for (int a = 0; a < 3; ++a) {
    if (!angular[a])
      continue;
    std::vector<ParamBox> next;
    for (const ParamBox& b : boxes) {
      const int n =
          std::max(1, static_cast<int>(std::ceil((b.hi[a] - b.lo[a]) / max_angle - 1e-9)));
      for (int k = 0; k < n; ++k) {
        ParamBox s = b;
        s.lo[a] = b.lo[a] + (b.hi[a] - b.lo[a]) * k / n;
        s.hi[a] = k + 1 == n ? b.hi[a] : b.lo[a] + (b.hi[a] - b.lo[a]) * (k + 1) / n;
        next.push_back(s);
      }
    }
    boxes = std::move(next);
  }
  return boxes;
}

// Bernstein ellipse parameter rho_B = (1 / tol)^(1/(2n)), distance in half-lengths
// cosh(ln rho_B), with the box radius standing in for the half-length. The margins this
// leaves (the radius exceeds the half-length, the worst direction is rare) were calibrated on
// the 32-magnet benchmark: the maximum field error relative to the peak field then stays
// below `tolerance` (tested).
double acceptance_ratio(double tolerance, int order) {
  const double t = std::log(1.0 / tolerance) / (2.0 * order);
  return std::max(1.0, std::cosh(t));
}

std::array<ParamBox, 2> split_box(const ParamBox& sub, int axis) {
  std::array<ParamBox, 2> halves{sub, sub};
  const double mid = 0.5 * (sub.lo[axis] + sub.hi[axis]);
  halves[0].hi[axis] = mid;
  halves[1].lo[axis] = mid;
  return halves;
}

bool magnet_contains(const AnalyticMagnet& magnet, const Eigen::Vector3d& x) {
  const Vec3 p = magnet.placement.to_local(x);
  if (const auto* s = std::get_if<SphericalSegment>(&magnet.shape)) {
    const double r = p.norm();
    if (r < s->r_inner || r > s->r_outer)
      return false;
    if (r == 0)
      return s->theta_min == 0;
    const double theta = std::acos(std::clamp(p.z() / r, -1.0, 1.0));
    if (theta < s->theta_min || theta > s->theta_max)
      return false;
    if (s->phi_max - s->phi_min >= 2 * pi)
      return true;
    double phi = std::atan2(p.y(), p.x());
    phi = s->phi_min + std::fmod(std::fmod(phi - s->phi_min, 2 * pi) + 2 * pi, 2 * pi);
    return phi <= s->phi_max;
  }
  if (const auto* c = std::get_if<Cylinder>(&magnet.shape)) {
    const double r = std::hypot(p.x(), p.y());
    return r >= c->r_inner && r <= c->r_outer && p.z() >= 0 && p.z() <= c->height;
  }
  if (const auto* b = std::get_if<Box>(&magnet.shape))
    return (p.cwiseAbs() - b->size / 2).maxCoeff() <= 0;
  return false;
}

} // namespace magfem
