#include "analytic/axisymmetric_interaction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {
namespace {

using Vec3 = Eigen::Vector3d;

// Relative tolerance for "centred", "full phi range" and "parallel to the axis": the
// placements come from rotations of exact data, so only round-off is forgiven.
constexpr double geometric_tolerance = 1e-9;

// I_k = int_{x2}^{x1} P_k(x) dx for k = 0..k_max, from int P_k = (P_{k+1} - P_{k-1}) / (2k+1).
std::vector<double> legendre_integrals(double x1, double x2, int k_max) {
  auto antiderivatives = [k_max](double x) {
    std::vector<double> p(static_cast<std::size_t>(k_max) + 2), f(k_max + 1);
    p[0] = 1, p[1] = x;
    for (int j = 1; j + 1 <= k_max + 1; ++j)
      p[j + 1] = ((2 * j + 1) * x * p[j] - j * p[j - 1]) / (j + 1);
    f[0] = x;
    for (int k = 1; k <= k_max; ++k)
      f[k] = (p[k + 1] - p[k - 1]) / (2 * k + 1);
    return f;
  };
  const auto f1 = antiderivatives(x1), f2 = antiderivatives(x2);
  std::vector<double> out(k_max + 1);
  for (int k = 0; k <= k_max; ++k)
    out[k] = f1[k] - f2[k];
  return out;
}

// |I_k| <= min(x1 - x2, 4 / (2k+1)) since |P_k| <= 1 on [-1, 1].
double legendre_integral_bound(double x1, double x2, int k) {
  return k == 0 ? x1 - x2 : std::min(x1 - x2, 4.0 / (2 * k + 1));
}

// Moments of one group, scaled so that no power overflows, and their upper bounds (index n).
struct Moments {
  std::vector<double> value, bound;
};

// q_n = a^(n+2) value[n]: int M . grad(r^n P_n) dV = 2 pi M n int r^(n+1) dr I_k, with
// k = n - 1 for parallel (d/dz (r^n P_n) = n r^(n-1) P_{n-1}) and k = n for radial.
void add_interior(const AxisymmetricBody& body, double a, int n_max, Moments& out) {
  const double x1 = std::cos(body.theta_min), x2 = std::cos(body.theta_max);
  const auto integral = legendre_integrals(x1, x2, n_max);
  for (int n = 1; n <= n_max; ++n) {
    const double radial =
        (std::pow(body.r_outer / a, n + 2) - std::pow(body.r_inner / a, n + 2)) / (n + 2);
    const int k = body.radial ? n : n - 1;
    const double common = 2 * pi * n * radial;
    out.value[n] += common * body.M * integral[k];
    out.bound[n] += common * std::abs(body.M) * legendre_integral_bound(x1, x2, k);
  }
}

// Q_n = b^(1-n) value[n]: int M . grad(r^-(n+1) P_n) dV = -2 pi M (n+1) int r^-n dr I_k, with
// k = n + 1 for parallel (d/dz (r^-(n+1) P_n) = -(n+1) r^-(n+2) P_{n+1}) and k = n for radial.
void add_exterior(const AxisymmetricBody& body, double b, int n_max, Moments& out) {
  const double x1 = std::cos(body.theta_min), x2 = std::cos(body.theta_max);
  const auto integral = legendre_integrals(x1, x2, n_max + 1);
  const double s1 = body.r_inner / b, s2 = body.r_outer / b; // >= 1
  for (int n = 1; n <= n_max; ++n) {
    const double radial =
        n == 1 ? std::log(s2 / s1) : (std::pow(s1, 1 - n) - std::pow(s2, 1 - n)) / (n - 1);
    const int k = body.radial ? n : n + 1;
    const double common = 2 * pi * (n + 1) * radial;
    out.value[n] -= common * body.M * integral[k];
    out.bound[n] += common * std::abs(body.M) * legendre_integral_bound(x1, x2, k);
  }
}

struct Groups {
  std::vector<AxisymmetricBody> inner, outer;
  double a = 0, b = 0; // inner bodies within a, outer ones beyond b > a
};

std::vector<AxisymmetricBody> bodies_of(const std::vector<AnalyticMagnet>& magnets) {
  std::vector<AxisymmetricBody> out;
  for (const auto& m : magnets) {
    std::string why;
    const auto body = axisymmetric_body(m, &why);
    if (!body)
      throw std::invalid_argument("magnet '" + m.name + "': " + why);
    if (body->M != 0)
      out.push_back(*body);
  }
  return out;
}

Moments moments(const Groups& g, bool interior, int n_max) {
  Moments m{std::vector<double>(n_max + 1, 0.0), std::vector<double>(n_max + 1, 0.0)};
  for (const auto& body : interior ? g.inner : g.outer)
    interior ? add_interior(body, g.a, n_max, m) : add_exterior(body, g.b, n_max, m);
  return m;
}

// Upper bounds of the degree-n terms of |torque| and |force| (their common factor mu0/4pi
// included), for n = 0..n_max.
struct TermBounds {
  std::vector<double> torque, force;
};

TermBounds term_bounds(const Groups& g, const Moments& q, const Moments& Q, int n_max) {
  const double rho = g.a / g.b, c = mu0 / (4 * pi);
  TermBounds t{std::vector<double>(n_max + 1, 0.0), std::vector<double>(n_max + 1, 0.0)};
  for (int n = 1; n <= n_max; ++n) {
    const double geometric = std::pow(rho, n - 1);
    // |sin(gamma) P_n'(cos gamma)| = |P_n^1| <= sqrt(n(n+1)/2) (addition theorem at one point).
    t.torque[n] =
        c * g.a * g.a * g.a * geometric * q.bound[n] * Q.bound[n] * std::sqrt(0.5 * n * (n + 1.0));
    // |n P_n a + P_n' (b - c a)|^2 = n^2 P_n^2 + (P_n^1)^2 (the two parts are orthogonal).
    if (n >= 2)
      t.force[n] = c * g.a * g.a * geometric * q.bound[n - 1] * Q.bound[n] *
                   std::sqrt(double(n) * n + 0.5 * n * (n + 1.0));
  }
  return t;
}

// Smallest n_max whose tails of both bounds are below tolerance times their sums; the bounds
// are computed to a length L at which the remainder beyond L, bounded geometrically (the
// algebraic factors are non-increasing there), is negligible.
struct Truncation {
  int n_max = 0;
  double torque_bound = 0, force_bound = 0;
};

Truncation choose_truncation(const Groups& g, const AxisymmetricInteractionOptions& o) {
  const double rho = g.a / g.b;
  for (int length = 64;; length *= 2) {
    if (length > 2 * o.n_limit)
      throw std::domain_error("harmonic interaction: the gap between the groups is too small "
                              "for " +
                              std::to_string(o.n_limit) + " degrees");
    const Moments q = moments(g, true, length), Q = moments(g, false, length);
    const TermBounds t = term_bounds(g, q, Q, length);
    double sum_t = 0, sum_f = 0;
    for (int n = 1; n <= length; ++n)
      sum_t += t.torque[n], sum_f += t.force[n];
    const double rest_t = t.torque[length] * rho / (1 - rho);
    const double rest_f = t.force[length] * rho / (1 - rho);
    if (rest_t > 1e-3 * o.tolerance * sum_t || rest_f > 1e-3 * o.tolerance * sum_f)
      continue;
    double tail_t = rest_t, tail_f = rest_f;
    int n = length;
    while (n > 1 && tail_t + t.torque[n] <= o.tolerance * sum_t &&
           tail_f + t.force[n] <= o.tolerance * sum_f)
      tail_t += t.torque[n], tail_f += t.force[n], --n;
    if (n > o.n_limit)
      throw std::domain_error("harmonic interaction: more than " + std::to_string(o.n_limit) +
                              " degrees needed");
    return {n, tail_t, tail_f};
  }
}

} // namespace

std::optional<AxisymmetricBody> axisymmetric_body(const AnalyticMagnet& magnet, std::string* why) {
  auto refuse = [why](const std::string& reason) -> std::optional<AxisymmetricBody> {
    if (why)
      *why = reason;
    return std::nullopt;
  };
  const auto* seg = std::get_if<SphericalSegment>(&magnet.shape);
  if (!seg)
    return refuse("not a spherical segment");
  if (seg->phi_max - seg->phi_min < 2 * pi * (1 - geometric_tolerance))
    return refuse("its phi range is not a full turn (not axisymmetric)");
  const double size = seg->r_outer;
  if (magnet.placement.translation.norm() > geometric_tolerance * size)
    return refuse("not centred on the origin");
  AxisymmetricBody body;
  body.axis = (magnet.placement.rotation * Vec3::UnitZ()).normalized();
  body.r_inner = seg->r_inner, body.r_outer = seg->r_outer;
  body.theta_min = seg->theta_min, body.theta_max = seg->theta_max;
  const double m0 = magnet.magnetization.sign * magnet.B_r / mu0;
  switch (magnet.magnetization.pattern) {
  case Magnetization::Pattern::none:
    break;
  case Magnetization::Pattern::parallel: {
    const Vec3 d = magnet.magnetization.direction.normalized();
    if (d.cross(body.axis).norm() > geometric_tolerance)
      return refuse("magnetized parallel but not along its own axis");
    body.M = m0 * d.dot(body.axis);
    break;
  }
  case Magnetization::Pattern::radial:
    if (magnet.magnetization.center.norm() > geometric_tolerance * size)
      return refuse("radial about a centre other than the origin");
    body.radial = true;
    body.M = m0;
    break;
  }
  return body;
}

AxisymmetricMoments axisymmetric_source_moments(const AxisymmetricBody& body, double a, int n_max) {
  Moments m{std::vector<double>(n_max + 1, 0.0), std::vector<double>(n_max + 1, 0.0)};
  add_interior(body, a, n_max, m);
  return {std::move(m.value), std::move(m.bound)};
}

AxisymmetricInteraction axisymmetric_interaction(const std::vector<AnalyticMagnet>& on,
                                                 const std::vector<AnalyticMagnet>& by,
                                                 const AxisymmetricInteractionOptions& options) {
  const auto on_bodies = bodies_of(on), by_bodies = bodies_of(by);
  AxisymmetricInteraction out;
  if (on_bodies.empty() || by_bodies.empty())
    return out; // nothing magnetized on one side
  auto reach = [](const std::vector<AxisymmetricBody>& bodies) {
    double lo = bodies.front().r_inner, hi = bodies.front().r_outer;
    for (const auto& b : bodies)
      lo = std::min(lo, b.r_inner), hi = std::max(hi, b.r_outer);
    return std::pair{lo, hi};
  };
  const auto [on_lo, on_hi] = reach(on_bodies);
  const auto [by_lo, by_hi] = reach(by_bodies);
  Groups g;
  bool on_inside = true;
  if (on_hi < by_lo)
    g = {on_bodies, by_bodies, on_hi, by_lo};
  else if (by_hi < on_lo)
    g = {by_bodies, on_bodies, by_hi, on_lo}, on_inside = false;
  else
    throw std::invalid_argument("the two groups are not separated by a sphere about the origin");

  const Truncation tr = choose_truncation(g, options);
  const int n_max = tr.n_max;
  // Per pair: each has its own angle between the axes. O(n_max) each.
  const double rho = g.a / g.b, c0 = mu0 / (4 * pi);
  std::vector<double> p(n_max + 1), dp(n_max + 1);
  for (const auto& A : g.inner) {
    Moments qa{std::vector<double>(n_max + 1, 0.0), std::vector<double>(n_max + 1, 0.0)};
    add_interior(A, g.a, n_max, qa);
    for (const auto& B : g.outer) {
      Moments qb{std::vector<double>(n_max + 1, 0.0), std::vector<double>(n_max + 1, 0.0)};
      add_exterior(B, g.b, n_max, qb);
      const double c = std::clamp(A.axis.dot(B.axis), -1.0, 1.0);
      // P_n(c) and P_n'(c) by their recurrences (P'_{n+1} = P'_{n-1} + (2n+1) P_n is a sum,
      // stable up to c = +-1 where P_n' = +-n(n+1)/2).
      p[0] = 1, dp[0] = 0;
      if (n_max >= 1)
        p[1] = c, dp[1] = 1;
      for (int n = 1; n < n_max; ++n) {
        p[n + 1] = ((2 * n + 1) * c * p[n] - n * p[n - 1]) / (n + 1);
        dp[n + 1] = dp[n - 1] + (2 * n + 1) * p[n];
      }
      double energy = 0, dw_dc = 0;
      Vec3 force = Vec3::Zero();
      const Vec3 across = B.axis - c * A.axis; // |across| = sin(gamma), normal to A's axis
      for (int n = 1; n <= n_max; ++n) {
        const double geometric = std::pow(rho, n - 1);
        if (geometric == 0)
          break;
        const double w = g.a * g.a * g.a * geometric * qa.value[n] * qb.value[n];
        energy += w * p[n];
        dw_dc += w * dp[n];
        if (n >= 2)
          force -= g.a * g.a * geometric * qa.value[n - 1] * qb.value[n] *
                   (n * p[n] * A.axis + dp[n] * across);
      }
      out.energy += c0 * energy;
      out.torque -= c0 * dw_dc * A.axis.cross(B.axis);
      out.force += c0 * force;
    }
  }
  if (!on_inside)
    out.force = -out.force, out.torque = -out.torque;
  out.n_max = n_max;
  out.torque_bound = tr.torque_bound;
  out.force_bound = tr.force_bound;
  return out;
}

} // namespace magfem
