#include "sources/straight_bundle.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {

namespace {

// (cos t1 - cos t2) / d^2 for a point at axial coordinates s1 (from the start) and s2 = s1 - L
// (from the end), at distance^2 d2 from the line. Beyond the ends (s1 s2 > 0) the two cosines
// are both near +-1 and their difference is rewritten as d2 (s1^2 - s2^2) / (r1 r2 (s1 r2 + s2
// r1)), which has neither the cancellation nor the division by d2.
double filament_factor(double s1, double s2, double d2) {
  const double r1 = std::sqrt(s1 * s1 + d2), r2 = std::sqrt(s2 * s2 + d2);
  if (s1 * s2 > 0) {
    return (s1 * s1 - s2 * s2) / (r1 * r2 * (s1 * r2 + s2 * r1));
  }
  if (!(d2 > 0)) {
    return 0.0; // on the filament
  }
  return (s1 / r1 - s2 / r2) / d2;
}

double interval_distance(double x, double lo, double hi) {
  return std::max({lo - x, 0.0, x - hi});
}

} // namespace

Vec3 straight_filament_field(const Vec3& start, const Vec3& t, double length, double current,
                             const Vec3& x) {
  const Vec3 r = x - start;
  const double s1 = r.dot(t);
  const Vec3 d = r - s1 * t;
  return current / (4.0 * pi) * filament_factor(s1, s1 - length, d.squaredNorm()) * t.cross(d);
}

StraightBundle::StraightBundle(const Vec3& origin, const Vec3& t, const Vec3& e_p, double length,
                               double width, double height, double current,
                               const CoilFieldOptions& options)
    : origin_(origin), t_(t.normalized()), e_p_(e_p.normalized()), e_q_(t_.cross(e_p_)),
      length_(length), width_(width), height_(height), options_(options) {
  check_options(options);
  if (!(length > 0 && width > 0 && height > 0)) {
    throw std::invalid_argument("StraightBundle: length, width and height must be positive");
  }
  current_density_ = current / (width * height);
}

void StraightBundle::add_filament(double p, double q, double di, double s, double px, double qx,
                                  double& hp, double& hq) const {
  const double dp = px - p, dq = qx - q;
  const double f = di / (4.0 * pi) * filament_factor(s, s - length_, dp * dp + dq * dq);
  // t x (dp e_p + dq e_q) = dp e_q - dq e_p
  hp -= f * dq;
  hq += f * dp;
}

// The cross-section integrand is singular where the filament through (p, q) passes through the
// field point: (p - px)^2 + (q - qx)^2 + e^2 = 0, e the axial distance beyond the bundle's ends
// (0 within them). Hence the p-integral's singularity at px +- i sqrt(dist(qx)^2 + e^2), and
// likewise for q. Within the span the kernel is 1/d; the near rule also resolves, by its radial
// grading, the scale of the filaments' ends when the point lies close to an end plane.
Vec3 StraightBundle::H(const Vec3& x) const {
  const Vec3 r = x - origin_;
  const double s = r.dot(t_), px = r.dot(e_p_), qx = r.dot(e_q_);
  const double e = interval_distance(s, 0.0, length_);
  const double dist_p = interval_distance(px, 0.0, width_);
  const double dist_q = interval_distance(qx, 0.0, height_);
  const double tol = options_.tolerance;
  const int n_max = options_.far_order_max;
  const int np =
      gauss_order_for(0.5 * width_, 0.5 * width_, px, std::hypot(dist_q, e), tol, 2, n_max);
  const int nq =
      gauss_order_for(0.5 * height_, 0.5 * height_, qx, std::hypot(dist_p, e), tol, 2, n_max);
  double hp = 0, hq = 0;
  if (np <= n_max && nq <= n_max) {
    const QuadratureRule& gp = cached_gauss(np);
    const QuadratureRule& gq = cached_gauss(nq);
    const double area = 0.25 * width_ * height_;
    for (std::size_t i = 0; i < gp.x.size(); ++i) {
      const double p = 0.5 * width_ * (1.0 + gp.x[i]);
      for (std::size_t j = 0; j < gq.x.size(); ++j) {
        const double q = 0.5 * height_ * (1.0 + gq.x[j]);
        add_filament(p, q, current_density_ * area * gp.w[i] * gq.w[j], s, px, qx, hp, hq);
      }
    }
  } else {
    const double d_cs = std::hypot(dist_p, dist_q);
    NearPoint np_;
    np_.u = px;
    np_.v = qx;
    np_.su = np_.sv = 1.0;
    if (e > 0) {
      np_.width = std::hypot(d_cs, e);
    } else {
      np_.width = d_cs > 0 ? d_cs : std::min(s, length_ - s);
    }
    np_.singular = d_cs == 0 && e == 0;
    np_.n = options_.near_order;
    thread_local std::vector<Node2> nodes;
    nodes.clear();
    append_near_rule({0.0, width_, 0.0, height_}, np_, nodes);
    for (const Node2& node : nodes) {
      add_filament(node.u, node.v, current_density_ * node.w, s, px, qx, hp, hq);
    }
  }
  return hp * e_p_ + hq * e_q_;
}

} // namespace magfem
