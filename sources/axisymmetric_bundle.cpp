#include "sources/axisymmetric_bundle.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {

namespace {

// Coefficients beyond the terms used, so that the tail bound of ZonalExpansion sees the
// coefficients the truncation drops.
constexpr int extra_terms = 40;

ZonalExpansion make_expansion(ZonalExpansion::Kind kind, double center, double radius,
                              std::vector<double> coefficients, const CoilFieldOptions& o) {
  if (!o.use_expansions || !(radius > 0)) {
    return {};
  }
  return ZonalExpansion(kind, center, radius, std::move(coefficients), o.tolerance,
                        o.expansion_terms);
}

} // namespace

AxisymmetricBundle::AxisymmetricBundle(const SphericalCoil& c, double current,
                                       const CoilFieldOptions& options)
    : spherical_(true), rect_{c.r_inner, c.r_outer, c.alpha_min, c.alpha_max}, options_(options) {
  check_options(options);
  if (!(c.r_inner >= 0 && c.r_outer > c.r_inner && c.alpha_min >= 0 && c.alpha_max > c.alpha_min &&
        c.alpha_max <= pi)) {
    throw std::invalid_argument("SphericalCoil: need 0 <= r_inner < r_outer and "
                                "0 <= alpha_min < alpha_max <= pi");
  }
  current_density_ = current / (0.5 * (c.r_outer * c.r_outer - c.r_inner * c.r_inner) *
                                (c.alpha_max - c.alpha_min));
  if (options.use_expansions) {
    build_exterior();
    if (c.r_inner > 0) {
      const int n = options.expansion_terms + extra_terms;
      interior_ = make_expansion(ZonalExpansion::Kind::interior, 0.0, c.r_inner,
                                 spherical_coil_interior_coefficients(c, current, n), options);
    }
  }
  build_rules();
}

AxisymmetricBundle::AxisymmetricBundle(const Solenoid& c, double current,
                                       const CoilFieldOptions& options)
    : spherical_(false), rect_{c.r_inner, c.r_outer, -0.5 * c.length, 0.5 * c.length},
      options_(options) {
  check_options(options);
  if (!(c.r_inner >= 0 && c.r_outer > c.r_inner && c.length > 0)) {
    throw std::invalid_argument("Solenoid: need 0 <= r_inner < r_outer and length > 0");
  }
  current_density_ = current / ((c.r_outer - c.r_inner) * c.length);
  if (options.use_expansions) {
    build_exterior();
    if (c.r_inner > 0) {
      const int n = options.expansion_terms + extra_terms;
      interior_ = make_expansion(ZonalExpansion::Kind::interior, 0.0, c.r_inner,
                                 solenoid_interior_coefficients(c, current, n), options);
    }
  }
  build_rules();
}

// The exterior expansion's centre minimizes the radius of the enclosing sphere: the farthest
// point of the cross-section from an axis point is one of its four corners (the squared
// distance is convex in u and monotone in cos v), and the largest of four convex functions
// of the centre is minimized by ternary search. Its coefficients are exact for a tensor
// Gauss rule of degree n + 2 in u; in v, for the spherical map, the integrand is a
// trigonometric polynomial of degree n + 1, whose Legendre coefficients on an interval of
// half-width h die out beyond degree ~ e (n + 1) h / 2: 0.7 (n + 1) h + 20 points suffice.
void AxisymmetricBundle::build_exterior() {
  const int n = options_.expansion_terms + extra_terms;
  std::vector<std::pair<double, double>> corners; // (a, z0)
  for (const double u : {rect_.u0, rect_.u1}) {
    for (const double v : {rect_.v0, rect_.v1}) {
      double a, z0, di;
      loops_at(u, v, 0.0, a, z0, di);
      corners.emplace_back(a, z0);
    }
  }
  auto enclosing = [&](double zc) {
    double r = 0;
    for (const auto& [a, z0] : corners) {
      r = std::max(r, std::hypot(a, z0 - zc));
    }
    return r;
  };
  double lo = corners.front().second, hi = lo;
  for (const auto& corner : corners) {
    lo = std::min(lo, corner.second);
    hi = std::max(hi, corner.second);
  }
  for (int it = 0; it < 200 && hi - lo > 1e-15 * (1.0 + std::abs(hi)); ++it) {
    const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
    if (enclosing(m1) < enclosing(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  const double center = 0.5 * (lo + hi);
  const double radius = enclosing(center);
  const int nu = n / 2 + 4;
  const int nv = spherical_ ? static_cast<int>(0.35 * (n + 1) * (rect_.v1 - rect_.v0)) + 20 : nu;
  const QuadratureRule gu = gauss_legendre(nu, rect_.u0, rect_.u1);
  const QuadratureRule gv = gauss_legendre(nv, rect_.v0, rect_.v1);
  std::vector<LoopSample> loops;
  loops.reserve(gu.x.size() * gv.x.size());
  for (std::size_t i = 0; i < gu.x.size(); ++i) {
    for (std::size_t j = 0; j < gv.x.size(); ++j) {
      LoopSample l;
      loops_at(gu.x[i], gv.x[j], gu.w[i] * gv.w[j], l.a, l.z0, l.current);
      loops.push_back(l);
    }
  }
  exterior_ = make_expansion(ZonalExpansion::Kind::exterior, center, radius,
                             exterior_coefficients(loops, center, radius, n), options_);
}

void AxisymmetricBundle::build_rules() {
  for (int n = 1; n <= options_.far_order_max; ++n) {
    const QuadratureRule& g = cached_gauss(n);
    Rule1 ru, rv;
    const double hu = 0.5 * (rect_.u1 - rect_.u0), mu = 0.5 * (rect_.u0 + rect_.u1);
    const double hv = 0.5 * (rect_.v1 - rect_.v0), mv = 0.5 * (rect_.v0 + rect_.v1);
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      const double u = mu + hu * g.x[i], v = mv + hv * g.x[i];
      ru.x.push_back(u);
      // The spherical map's area element r dr dalpha: fold r into the u weights.
      ru.w.push_back(hu * g.w[i] * (spherical_ ? u : 1.0));
      rv.x.push_back(v);
      rv.w.push_back(hv * g.w[i]);
      rv.sin_x.push_back(std::sin(v));
      rv.cos_x.push_back(std::cos(v));
    }
    u_rules_.push_back(std::move(ru));
    v_rules_.push_back(std::move(rv));
  }
}

double AxisymmetricBundle::meridian_distance(double rho, double z) const {
  if (!spherical_) {
    const double dx = std::max({rect_.u0 - rho, 0.0, rho - rect_.u1});
    const double dz = std::max({rect_.v0 - z, 0.0, z - rect_.v1});
    return std::hypot(dx, dz);
  }
  const double r = std::hypot(rho, z), alpha = std::atan2(rho, z);
  if (alpha >= rect_.v0 && alpha <= rect_.v1) {
    return std::max({rect_.u0 - r, 0.0, r - rect_.u1});
  }
  // Nearest radial edge of the annular sector; the projection onto it is clamped to its ends.
  const double edge = alpha < rect_.v0 ? rect_.v0 : rect_.v1;
  const double t = std::clamp(r * std::cos(alpha - edge), rect_.u0, rect_.u1);
  return std::hypot(rho - t * std::sin(edge), z - t * std::cos(edge));
}

void AxisymmetricBundle::loops_at(double u, double v, double w, double& a, double& z0,
                                  double& di) const {
  if (spherical_) {
    a = u * std::sin(v);
    z0 = u * std::cos(v);
    di = current_density_ * u * w;
  } else {
    a = u;
    z0 = v;
    di = current_density_ * w;
  }
}

MeridianField AxisymmetricBundle::H(double rho, double z) const {
  MeridianField h;
  if (exterior_.evaluate(rho, z, h) || interior_.evaluate(rho, z, h)) {
    return h;
  }
  return H_integrated(rho, z);
}

namespace {

// Distance from x to the interval [lo, hi] (0 inside).
double interval_distance(double x, double lo, double hi) {
  return std::max({lo - x, 0.0, x - hi});
}

} // namespace

// The loop kernel is singular where the loop passes through the field point P:
// (a - rho)^2 + (z0 - z)^2 = 0. For the solenoid (a, z0) = (u, v) this puts the singularity
// of the u-integral at u = rho +- i dist(z, [v0, v1]) and that of the v-integral at
// v = z +- i dist(rho, [u0, u1]). For the spherical coil (a, z0) = u (sin v, cos v), P at
// (R sin A, R cos A), it becomes u^2 + R^2 - 2 u R cos(v - A) = 0: u = R e^{+-i(v - A)},
// v = A +- i ln(R/u) (A also mirrored to -A and 2 pi - A, the same loop seen from the other
// side of the axis). The orders follow from the nearest such point (gauss_order_for).
void AxisymmetricBundle::far_orders(double rho, double z, int& nu, int& nv) const {
  const double tol = options_.tolerance;
  const int n_max = options_.far_order_max, n_min = 2;
  const double mu = 0.5 * (rect_.u0 + rect_.u1), hu = 0.5 * (rect_.u1 - rect_.u0);
  const double mv = 0.5 * (rect_.v0 + rect_.v1), hv = 0.5 * (rect_.v1 - rect_.v0);
  if (!spherical_) {
    nu = gauss_order_for(mu, hu, rho, interval_distance(z, rect_.v0, rect_.v1), tol, n_min, n_max,
                         2, 0.0);
    nv = gauss_order_for(mv, hv, z, interval_distance(rho, rect_.u0, rect_.u1), tol, n_min, n_max);
    return;
  }
  const double r = std::hypot(rho, z), angle = std::atan2(rho, z);
  double image = angle, delta = interval_distance(angle, rect_.v0, rect_.v1);
  for (const double other : {-angle, 2.0 * pi - angle}) {
    const double d = interval_distance(other, rect_.v0, rect_.v1);
    if (d < delta) {
      delta = d;
      image = other;
    }
  }
  nu = gauss_order_for(mu, hu, r * std::cos(delta), r * std::sin(delta), tol, n_min, n_max, 3, 0.0);
  const double eta = r > 0 ? interval_distance(std::log(r), std::log(rect_.u0), std::log(rect_.u1))
                           : std::numeric_limits<double>::infinity();
  // The integrand also carries sin^2(v) and cos(v) factors, entire but growing off the real
  // axis: far from the bundle they, not the singularity, set the order.
  nv = std::max(gauss_order_for(mv, hv, image, std::min(eta, 1e3), tol, n_min, n_max),
                gauss_order_entire(2.0, hv, tol, n_min, n_max));
}

MeridianField AxisymmetricBundle::H_integrated(double rho, double z) const {
  const int n_max = options_.far_order_max;
  int nu, nv;
  far_orders(rho, z, nu, nv);
  MeridianField h;
  if (nu <= n_max && nv <= n_max) {
    const Rule1& ru = u_rules_[static_cast<std::size_t>(nu - 1)];
    const Rule1& rv = v_rules_[static_cast<std::size_t>(nv - 1)];
    for (std::size_t i = 0; i < ru.x.size(); ++i) {
      for (std::size_t j = 0; j < rv.x.size(); ++j) {
        const double di = current_density_ * ru.w[i] * rv.w[j];
        const double a = spherical_ ? ru.x[i] * rv.sin_x[j] : ru.x[i];
        const double z0 = spherical_ ? ru.x[i] * rv.cos_x[j] : rv.x[j];
        const MeridianField f = loop_field(a, z0, di, rho, z);
        h.h_rho += f.h_rho;
        h.h_z += f.h_z;
      }
    }
    return h;
  }
  NearPoint p;
  if (spherical_) {
    p.u = std::hypot(rho, z);
    p.v = std::atan2(rho, z);
    p.su = 1.0;
    // Arc length per radian; kept away from zero for a cap reaching the sphere's centre, where
    // the map degenerates.
    p.sv = std::max(std::clamp(p.u, rect_.u0, rect_.u1), 1e-3 * rect_.u1);
  } else {
    p.u = rho;
    p.v = z;
    p.su = p.sv = 1.0;
  }
  p.width = meridian_distance(rho, z);
  p.singular = p.width == 0;
  p.n = options_.near_order;
  thread_local std::vector<Node2> nodes;
  nodes.clear();
  append_near_rule(rect_, p, nodes);
  for (const Node2& node : nodes) {
    double a, z0, di;
    loops_at(node.u, node.v, node.w, a, z0, di);
    const MeridianField f = loop_field(a, z0, di, rho, z);
    h.h_rho += f.h_rho;
    h.h_z += f.h_z;
  }
  return h;
}

} // namespace magfem
