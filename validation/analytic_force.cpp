#include "validation/analytic_force.hpp"

#include <cmath>
#include <mutex>
#include <thread>

#include "core/constants.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

struct SpherePoint {
  Vec3 x, n;
  double w; // area weight
};

std::vector<SpherePoint> sphere_points(const Vec3& c, double r, int n_theta, int n_phi) {
  const GaussRule g(n_theta);
  std::vector<SpherePoint> pts;
  pts.reserve(static_cast<std::size_t>(n_theta) * n_phi);
  for (int i = 0; i < n_theta; ++i) {
    // theta = (pi/2)(1 + t): d theta = pi/2 dt, dS = r^2 sin(theta) dtheta dphi.
    const double th = 0.5 * pi * (1 + g.nodes[i]);
    const double wt = 0.5 * pi * g.weights[i] * r * r * std::sin(th) * (2 * pi / n_phi);
    for (int j = 0; j < n_phi; ++j) {
      const double ph = 2 * pi * (j + 0.5) / n_phi;
      const Vec3 n(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      pts.push_back({c + r * n, n, wt});
    }
  }
  return pts;
}

ForceTorque integrate_stress(const std::vector<SpherePoint>& pts, const std::vector<Vec3>& B,
                             const Vec3& torque_point) {
  ForceTorque ft;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec3& b = B[i];
    // T.n = (1/mu0) (B (B.n) - n |B|^2 / 2)
    const Vec3 tn = (b * b.dot(pts[i].n) - 0.5 * b.squaredNorm() * pts[i].n) / mu0;
    ft.force += pts[i].w * tn;
    ft.torque += pts[i].w * (pts[i].x - torque_point).cross(tn);
  }
  return ft;
}

// Force and torque of the point charges of one box in the field H of `field`.
ForceTorque box_force(const ChargeDomain& d, const ParamBox& box, const GaussRule& rule,
                      const ChargeModel& field, const Vec3& p) {
  std::vector<PointCharge> q;
  d.quadrature(box, rule, q);
  ForceTorque ft;
  for (const PointCharge& c : q) {
    if (c.q == 0)
      continue;
    const Vec3 f = mu0 * c.q * field.H(c.x);
    ft.force += f;
    ft.torque += (c.x - p).cross(f);
  }
  return ft;
}

struct InteractionTask {
  const ChargeDomain* domain;
  ParamBox box;
  int depth;
  ForceTorque estimate;
};

// Adaptive bisection: accept a box when its two halves change force and torque by less than
// the absolute tolerances; return the halves' (more accurate) sum.
ForceTorque refine(const InteractionTask& t, const GaussRule& rule, const ChargeModel& field,
                   const Vec3& p, double f_tol, double t_tol, int max_depth) {
  const int axis = box_extent(*t.domain, t.box).longest_axis;
  const auto halves = split_box(t.box, axis);
  const ForceTorque a = box_force(*t.domain, halves[0], rule, field, p);
  const ForceTorque b = box_force(*t.domain, halves[1], rule, field, p);
  ForceTorque sum{a.force + b.force, a.torque + b.torque};
  const bool converged = (sum.force - t.estimate.force).norm() <= f_tol &&
                         (sum.torque - t.estimate.torque).norm() <= t_tol;
  if (converged || t.depth >= max_depth)
    return sum;
  const ForceTorque ra = refine({t.domain, halves[0], t.depth + 1, a}, rule, field, p, 0.5 * f_tol,
                                0.5 * t_tol, max_depth);
  const ForceTorque rb = refine({t.domain, halves[1], t.depth + 1, b}, rule, field, p, 0.5 * f_tol,
                                0.5 * t_tol, max_depth);
  return {ra.force + rb.force, ra.torque + rb.torque};
}

} // namespace

ForceTorque maxwell_stress_on_sphere(const FieldFunction& B, const Vec3& center, double radius,
                                     const Vec3& torque_point, int n_theta, int n_phi) {
  const std::vector<SpherePoint> pts = sphere_points(center, radius, n_theta, n_phi);
  std::vector<Vec3> b(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    b[i] = B(pts[i].x);
  return integrate_stress(pts, b, torque_point);
}

ForceTorque maxwell_stress_on_sphere(const BatchFieldFunction& B, const Vec3& center, double radius,
                                     const Vec3& torque_point, int n_theta, int n_phi) {
  const std::vector<SpherePoint> pts = sphere_points(center, radius, n_theta, n_phi);
  std::vector<Vec3> xs(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    xs[i] = pts[i].x;
  return integrate_stress(pts, B(xs), torque_point);
}

ForceTorque charge_interaction(const std::vector<AnalyticMagnet>& on,
                               const std::vector<AnalyticMagnet>& by, const Vec3& torque_point,
                               const ChargeInteractionOptions& options) {
  const ChargeModel field(by, {}, options.field);
  const GaussRule rule(options.gauss_order);
  std::vector<ChargeDomain> domains;
  for (const AnalyticMagnet& m : on)
    for (const ChargeDomain& d : charge_domains(m))
      domains.push_back(d);

  // First pass: whole faces, for the scale of the tolerance (sum of magnitudes, so that a
  // vanishing net force still gets a meaningful absolute tolerance).
  std::vector<InteractionTask> tasks;
  double f_scale = 0, t_scale = 0;
  for (const ChargeDomain& d : domains) {
    const std::vector<ParamBox> boxes = root_boxes(d, pi / 4);
    for (const ParamBox& b : boxes) {
      const ForceTorque ft = box_force(d, b, rule, field, torque_point);
      f_scale += ft.force.norm();
      t_scale += ft.torque.norm();
      tasks.push_back({&d, b, 0, ft});
    }
  }
  const double f_tol = options.tolerance * f_scale / tasks.size();
  const double t_tol = options.tolerance * t_scale / tasks.size();

  // Boxes are independent: share them among threads; sum in task order (deterministic).
  std::vector<ForceTorque> results(tasks.size());
  std::mutex mutex;
  std::size_t next = 0;
  auto work = [&] {
    for (;;) {
      std::size_t i;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= tasks.size())
          return;
        i = next++;
      }
      results[i] = refine(tasks[i], rule, field, torque_point, f_tol, t_tol, options.max_depth);
    }
  };
  const int n_threads = options.field.n_threads > 0
                            ? options.field.n_threads
                            : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<std::thread> threads;
  for (int t = 1; t < n_threads; ++t)
    threads.emplace_back(work);
  work();
  for (std::thread& th : threads)
    th.join();
  ForceTorque total;
  for (const ForceTorque& ft : results) {
    total.force += ft.force;
    total.torque += ft.torque;
  }
  return total;
}

} // namespace magfem
