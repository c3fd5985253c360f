#include "analytic/analytic_force.hpp"

#include <cmath>
#include <mutex>
#include <thread>

#include "core/constants.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

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

// Faces (and volumes) of the field's sources, for the distance test.
struct SourceBox {
  const ChargeDomain* domain;
  ParamBox box;
  BoxExtent extent;
};

struct InteractionContext {
  const GaussRule& rule;
  const ChargeModel& field;
  Vec3 torque_point;
  int max_depth;
  double ratio; // a box is resolved if the sources are >= ratio * its radius away
  std::vector<ChargeDomain> source_domains;
  std::vector<SourceBox> source_roots;
};

// The edges of a face as degenerate parameter boxes, except seams of full revolutions (the
// two edges coincide) and edges collapsed to a point (the pole of a sphere face).
void add_edges(const ChargeDomain& d, std::vector<SourceBox>& out) {
  if (d.dim != 2)
    return;
  const double size = box_extent(d, d.box).radius;
  for (int a = 0; a < 2; ++a) {
    std::array<double, 3> lo_mid{}, hi_mid{};
    for (int k = 0; k < 2; ++k)
      lo_mid[k] = hi_mid[k] = 0.5 * (d.box.lo[k] + d.box.hi[k]);
    lo_mid[a] = d.box.lo[a];
    hi_mid[a] = d.box.hi[a];
    if ((d.point(lo_mid) - d.point(hi_mid)).norm() < 1e-12 * size)
      continue; // seam
    for (double at : {d.box.lo[a], d.box.hi[a]}) {
      ChargeDomain edge = d;
      edge.box.lo[a] = edge.box.hi[a] = at;
      for (const ParamBox& piece : root_boxes(edge, pi / 4)) {
        const BoxExtent e = box_extent(d, piece);
        if (e.radius > 1e-12 * size)
          out.push_back({&d, piece, e});
      }
    }
  }
}

// True if every point of the source box is at least `threshold` from x (to 5 % of the
// threshold): branch and bound on box extents.
bool far_from(const SourceBox& s, const Vec3& x, double threshold) {
  const double dc = (x - s.extent.centre).norm();
  if (dc < threshold)
    return false;
  if (dc - s.extent.radius >= threshold || s.extent.radius < 0.05 * threshold)
    return true;
  for (const ParamBox& half : split_box(s.box, s.extent.longest_axis))
    if (!far_from({s.domain, half, box_extent(*s.domain, half)}, x, threshold))
      return false;
  return true;
}

// The field of the sources is smooth up to their faces from either side but singular at
// their edges; a Gauss rule over a box of the `on` magnets only converges when the edges lie
// a few box radii away. The error estimate (halves vs. whole) alone can be fooled by a narrow
// peak between the nodes.
bool resolved(const InteractionContext& ctx, const BoxExtent& e) {
  for (const SourceBox& s : ctx.source_roots)
    if (!far_from(s, e.centre, ctx.ratio * e.radius))
      return false;
  return true;
}

// Adaptive bisection: accept a box when it is resolved and its two halves change force and
// torque by less than the absolute tolerances; return the halves' (more accurate) sum.
ForceTorque refine(const InteractionTask& t, const InteractionContext& ctx, double f_tol,
                   double t_tol) {
  const BoxExtent e = box_extent(*t.domain, t.box);
  const auto halves = split_box(t.box, e.longest_axis);
  const Vec3& p = ctx.torque_point;
  const ForceTorque a = box_force(*t.domain, halves[0], ctx.rule, ctx.field, p);
  const ForceTorque b = box_force(*t.domain, halves[1], ctx.rule, ctx.field, p);
  ForceTorque sum{a.force + b.force, a.torque + b.torque};
  const bool converged = (sum.force - t.estimate.force).norm() <= f_tol &&
                         (sum.torque - t.estimate.torque).norm() <= t_tol && resolved(ctx, e);
  if (converged || t.depth >= ctx.max_depth)
    return sum;
  const ForceTorque ra =
      refine({t.domain, halves[0], t.depth + 1, a}, ctx, 0.5 * f_tol, 0.5 * t_tol);
  const ForceTorque rb =
      refine({t.domain, halves[1], t.depth + 1, b}, ctx, 0.5 * f_tol, 0.5 * t_tol);
  return {ra.force + rb.force, ra.torque + rb.torque};
}

} // namespace

ForceTorque charge_interaction(const std::vector<AnalyticMagnet>& on,
                               const std::vector<AnalyticMagnet>& by, const Vec3& torque_point,
                               const ChargeInteractionOptions& options) {
  const ChargeModel field(by, {}, options.field);
  const GaussRule rule(options.gauss_order);
  InteractionContext ctx{rule,
                         field,
                         torque_point,
                         options.max_depth,
                         acceptance_ratio(options.tolerance, options.gauss_order),
                         {},
                         {}};
  for (const AnalyticMagnet& m : by) {
    for (const ChargeDomain& d : charge_domains(m))
      ctx.source_domains.push_back(d);
    for (const ChargeDomain& d : current_domains(m))
      ctx.source_domains.push_back(d);
  }
  for (const ChargeDomain& d : ctx.source_domains)
    add_edges(d, ctx.source_roots);
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
      results[i] = refine(tasks[i], ctx, f_tol, t_tol);
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
