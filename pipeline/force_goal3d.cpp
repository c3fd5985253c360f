#include "pipeline/force_goal3d.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pipeline/adapt_loop.hpp"
#include "pipeline/force3d.hpp"
#include "pipeline/run3d.hpp"
#include "postproc/maxwell_stress3d.hpp"
#include "postproc/probe_error3d.hpp"

namespace magfem {
namespace {

// |a - b| of the quantity's component: a vector's norm for "force" and "torque", else the
// one component (Fx .. Tz).
double component_difference(const ForceTorque& a, const ForceTorque& b, const std::string& c) {
  if (c == "force")
    return (a.force - b.force).norm();
  if (c == "torque")
    return (a.torque - b.torque).norm();
  const Eigen::Vector3d d = c[0] == 'F' ? a.force - b.force : a.torque - b.torque;
  return std::abs(d[c[1] - 'x']);
}

// |dm_i| of every quadrature point: the point's contribution to the quantity from the
// element B against the reported nodal-average B.
std::vector<double> local_differences(const Run3D& run, const std::vector<SurfacePoint>& points,
                                      const ForceSpec& f, const std::string& component) {
  const PointLocator3D locator(run.mesh);
  const FieldSampler3D average(*run.field, locator);
  const FieldSampler3D element(*run.field, locator, FieldSampling::element);
  std::vector<Eigen::Vector3d> x;
  x.reserve(points.size());
  for (const auto& p : points)
    x.push_back(p.x);
  const std::vector<Eigen::Vector3d> b_avg = average.B(x), b_el = element.B(x);
  std::vector<double> d(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    d[i] =
        component_difference(maxwell_stress_sum({points[i]}, {b_avg[i]}, f.torque_point),
                             maxwell_stress_sum({points[i]}, {b_el[i]}, f.torque_point), component);
  return d;
}

// The sources of one force quantity (force_goal3d.hpp).
void add_force_sources(const Run3D& run, const AdaptQuantity& q, const ForceSpec& f,
                       double accuracy_pct, const std::vector<double>& h, double floor,
                       std::vector<SizeSample3D>& out) {
  const double value = std::abs(adapt_quantity_value(q, 0, run.forces, {}, {}));
  const double estimate_pct = adapt_quantity_mesh_error_pct(q, run.forces);
  if (!(value > 0) || !(estimate_pct > 0) || !std::isfinite(estimate_pct))
    return;
  const std::vector<SurfacePoint> points = force_surface_points(f);
  std::vector<double> d;
  try {
    d = local_differences(run, points, f, q.component);
  } catch (const std::invalid_argument&) {
    return; // the reported force sampled the same points, so this cannot happen
  }
  double sum_d = 0, area = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    sum_d += d[i], area += points[i].w;
  if (!(sum_d > 0) || !(area > 0))
    return;
  const double error = estimate_pct / 100 * value;
  const double aim = aim_below_target * std::min(accuracy_pct, estimate_pct) / 100 * value;
  const double power = 1.0 / (2.0 * run.spec.order);
  std::vector<Eigen::Vector3d> marked;
  std::vector<double> ratio;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double e = error * d[i] / sum_d, t = aim * points[i].w / area;
    if (e > t) {
      marked.push_back(points[i].x);
      ratio.push_back(std::max(min_force_ratio, std::pow(t / e, power)));
    }
  }
  const std::vector<TetPoint3D> found = locate_points(run.mesh, marked);
  if (found.size() != marked.size())
    return; // a point outside the mesh: not reached, the force was computed there
  for (std::size_t i = 0; i < found.size(); ++i)
    out.push_back({found[i].x, std::max(floor, h[found[i].tet] * ratio[i])});
}

} // namespace

std::vector<SizeSample3D>
force_goal_sources_3d(const Run3D& run, const std::vector<AdaptQuantity>& quantities,
                      double accuracy_pct, const std::vector<double>& h_requested, double floor) {
  std::vector<SizeSample3D> out;
  for (const auto& q : quantities) {
    if (q.kind != AdaptQuantity::Kind::force)
      continue;
    const auto f = std::find_if(run.spec.forces.begin(), run.spec.forces.end(),
                                [&](const ForceSpec& s) { return s.name == q.name; });
    if (f == run.spec.forces.end() ||
        (f->kind != ForceSpec::Kind::sphere && f->kind != ForceSpec::Kind::box))
      continue;
    add_force_sources(run, q, *f, accuracy_pct, h_requested, floor, out);
  }
  return out;
}

} // namespace magfem
