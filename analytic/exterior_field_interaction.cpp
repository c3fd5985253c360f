#include "analytic/exterior_field_interaction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/constants.hpp"
#include "analytic/axisymmetric_interaction.hpp"
#include "analytic/charge_source.hpp"
#include "analytic/gauss_error.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

constexpr double radius_margin = 1.1; // box_extent samples the image: allow for bulging
constexpr int min_order = 2;
constexpr int max_split_depth = 40;
constexpr double coarse_factor = 100; // tolerance of the run that estimates the error

struct Source {
  Vec3 axis;
  std::vector<double> value; // q_n / a^(n+2)
};

struct Context {
  std::vector<Source> sources;
  double a = 0;
  int n_max = 0;
  double tolerance = 0;
  int max_order = 0;
  Vec3 torque_point;
  std::vector<GaussRule> rules;
  std::vector<double> inverse; // 1 / (n + 1)
};

// Degree at which the series is cut at a point with a / r = s: the terms fall like
// s^(n-1) times at most (n+1)^2 / 2 relative to the first (|P_n'| <= n(n+1)/2), so the
// first n with s^(n-1) (n+1)^2 <= tolerance, capped by the global n_max.
int degree_at(const Context& c, double s) {
  const double log_tol = std::log(c.tolerance), log_s = std::log(s);
  int n = std::max(2, static_cast<int>(log_tol / log_s));
  // Solve (n - 1) log s + 2 log(n + 1) <= log tol by a few fixed-point steps.
  for (int k = 0; k < 4 && n < c.n_max; ++k)
    n = std::max(n, static_cast<int>(std::ceil(1 + (log_tol - 2 * std::log(n + 1.0)) / log_s)));
  return std::min(n, c.n_max);
}

// H at x (|x| > a), A/m.
Vec3 field(const Context& c, const Vec3& x) {
  const double r = x.norm(), s = c.a / r;
  const int n_cut = degree_at(c, s);
  const Vec3 xh = x / r;
  Vec3 h = Vec3::Zero();
  const double* inv = c.inverse.data();
  for (const Source& src : c.sources) {
    const double u = std::clamp(xh.dot(src.axis), -1.0, 1.0);
    const double* value = src.value.data();
    // P_n and P_n' by their recurrences (P'_{n+1} = P'_{n-1} + (2n+1) P_n, stable at u = +-1),
    // rolled in scalars: (p0, p1) = (P_{n-1}, P_n), likewise d0, d1.
    double p0 = 1, p1 = u, d0 = 0, d1 = 1;
    double radial = 0, tangential = 0, sn = s * s * s; // s^(n+2) at n = 1
    for (int n = 1; n <= n_cut; ++n) {
      radial += value[n] * sn * (n + 1) * p1;
      tangential += value[n] * sn * d1;
      const double p2 = ((2 * n + 1) * u * p1 - n * p0) * inv[n];
      const double d2 = d0 + (2 * n + 1) * p1;
      p0 = p1, p1 = p2, d0 = d1, d1 = d2, sn *= s;
    }
    h += radial * xh - tangential * (src.axis - u * xh);
  }
  return h / (4 * pi);
}

struct FieldBox {
  const ChargeDomain* domain;
  ParamBox box;
  Vec3 centre;
  double radius;
  int axis;
  double half_angle;
};

FieldBox make_box(const ChargeDomain* d, const ParamBox& b) {
  const BoxExtent e = box_extent(*d, b);
  const std::array<bool, 3> angular = angular_parameters(*d);
  double h = 0;
  for (int k = 0; k < 3; ++k)
    if (angular[k])
      h = std::max(h, 0.5 * (b.hi[k] - b.lo[k]));
  return {d, b, e.centre, radius_margin * e.radius, e.longest_axis, h};
}

void integrate(const Context& c, const FieldBox& b, int depth, std::vector<PointCharge>& q,
               ForceTorque& t) {
  const double rho = (b.centre.norm() - c.a) / b.radius;
  const int n = gauss_order(c.tolerance, rho, b.half_angle, min_order, c.max_order);
  if (n > c.max_order && depth < max_split_depth) {
    for (const ParamBox& half : split_box(b.box, b.axis))
      integrate(c, make_box(b.domain, half), depth + 1, q, t);
    return;
  }
  const int order = std::min(n, c.max_order);
  q.clear();
  b.domain->quadrature(b.box, c.rules[order], q);
  for (const PointCharge& pc : q) {
    if (pc.q == 0)
      continue;
    const Vec3 f = mu0 * pc.q * field(c, pc.x);
    t.force += f;
    t.torque += (pc.x - c.torque_point).cross(f);
  }
}

// Root boxes are independent: shared among threads, summed in box order (deterministic).
ForceTorque run(const Context& c, const std::vector<FieldBox>& roots, int n_threads) {
  std::vector<ForceTorque> results(roots.size());
  std::mutex mutex;
  std::size_t next = 0;
  auto work = [&] {
    std::vector<PointCharge> q;
    for (;;) {
      std::size_t i;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= roots.size())
          return;
        i = next++;
      }
      integrate(c, roots[i], 0, q, results[i]);
    }
  };
  std::vector<std::thread> threads;
  for (int k = 1; k < n_threads; ++k)
    threads.emplace_back(work);
  work();
  for (std::thread& th : threads)
    th.join();
  ForceTorque sum;
  for (const ForceTorque& r : results)
    sum = sum + r;
  return sum;
}

// Smallest |x| over the box's image, from below (split until the bounding spheres clear the
// sphere of radius a, or give up: the box reaches into it).
double min_radius(const ChargeDomain* d, const ParamBox& pb, double a, int depth) {
  const FieldBox b = make_box(d, pb);
  const double lo = b.centre.norm() - b.radius;
  if (lo > a || depth >= 16)
    return lo;
  double m = std::numeric_limits<double>::max();
  for (const ParamBox& half : split_box(pb, b.axis))
    m = std::min(m, min_radius(d, half, a, depth + 1));
  return m;
}

} // namespace

ExteriorFieldInteraction exterior_field_interaction(const std::vector<AnalyticMagnet>& on,
                                                    const std::vector<AnalyticMagnet>& by,
                                                    const Vec3& torque_point,
                                                    const ExteriorFieldOptions& options) {
  if (!(options.tolerance > 0 && options.tolerance < 1))
    throw std::invalid_argument("exterior_field_interaction: tolerance must lie in (0, 1)");
  std::vector<AxisymmetricBody> bodies;
  double a = 0;
  for (const AnalyticMagnet& m : by) {
    std::string why;
    const auto body = axisymmetric_body(m, &why);
    if (!body)
      throw std::invalid_argument("magnet '" + m.name + "': " + why);
    if (body->M != 0)
      bodies.push_back(*body);
    a = std::max(a, body->r_outer);
  }
  std::vector<ChargeDomain> domains;
  for (const AnalyticMagnet& m : on)
    for (const ChargeDomain& d : charge_domains(m))
      domains.push_back(d);
  std::vector<FieldBox> roots;
  double r_min = std::numeric_limits<double>::max();
  for (const ChargeDomain& d : domains)
    for (const ParamBox& pb : root_boxes(d, pi / 4)) {
      const double lo = min_radius(&d, pb, a, 0);
      if (!(lo > a))
        throw std::invalid_argument("magnet reaches into the sphere of radius " +
                                    std::to_string(a) + " m enclosing the axisymmetric group");
      r_min = std::min(r_min, lo);
      roots.push_back(make_box(&d, pb));
    }
  ExteriorFieldInteraction out;
  if (bodies.empty() || roots.empty())
    return out;

  // Global cap on the degrees: the rigorous tail of the term bounds at the smallest radius
  // (|P_n| <= 1, |P_n'| <= n(n+1)/2) below tolerance times their sum. Each point then stops
  // at its own degree (degree_at), far below the cap away from the sphere.
  const double s = a / r_min;
  int length = 64;
  std::vector<double> terms;
  for (;; length *= 2) {
    if (length > 2 * options.n_limit)
      throw std::domain_error("exterior field interaction: the charges come too close to the "
                              "sphere for " +
                              std::to_string(options.n_limit) + " degrees");
    terms.assign(length + 1, 0.0);
    for (const AxisymmetricBody& body : bodies) {
      const AxisymmetricMoments m = axisymmetric_source_moments(body, a, length);
      for (int n = 1; n <= length; ++n)
        terms[n] += m.bound[n] * std::pow(s, n + 2) * ((n + 1) + 0.5 * n * (n + 1.0));
    }
    double sum = 0;
    for (int n = 1; n <= length; ++n)
      sum += terms[n];
    if (terms[length] * s / (1 - s) <= 1e-3 * options.tolerance * sum)
      break;
  }
  double total = 0;
  for (int n = 1; n <= length; ++n)
    total += terms[n];
  double tail = terms[length] * s / (1 - s);
  int n_max = length;
  while (n_max > 1 && tail + terms[n_max] <= options.tolerance * total)
    tail += terms[n_max], --n_max;
  if (n_max > options.n_limit)
    throw std::domain_error("exterior field interaction: more than " +
                            std::to_string(options.n_limit) + " degrees needed");

  Context c;
  c.a = a, c.n_max = std::max(n_max, 1), c.tolerance = options.tolerance;
  c.max_order = std::max(min_order, options.max_order), c.torque_point = torque_point;
  for (const AxisymmetricBody& body : bodies)
    c.sources.push_back({body.axis, axisymmetric_source_moments(body, a, c.n_max).value});
  for (int n = 0; n <= c.max_order; ++n)
    c.rules.emplace_back(std::max(1, n));
  for (int n = 0; n <= c.n_max + 1; ++n)
    c.inverse.push_back(1.0 / (n + 1));

  const int n_threads = options.n_threads > 0
                            ? options.n_threads
                            : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  out.on = run(c, roots, n_threads);
  // Accuracy: the same at 100 x the tolerance (orders and degrees), whose difference from the
  // result bounds the coarser one's error in practice (geometric convergence) and so
  // overstates this one's.
  Context coarse = c;
  coarse.tolerance = std::min(0.1, coarse_factor * options.tolerance);
  const ForceTorque rough = run(coarse, roots, n_threads);
  out.force_error = (rough.force - out.on.force).norm();
  out.torque_error = (rough.torque - out.on.torque).norm();
  out.n_max = c.n_max;
  return out;
}

} // namespace magfem
