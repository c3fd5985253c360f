// Evaluators for thesis ch. 4 (003_8d5b5c90a0e7438f.txt): the spherical gravity compensator.
// Torque and force of the rotated outer magnet come from `magfem sweep` (studies/sweep.hpp):
// analytic charge interaction, and FE (Maxwell stress on a mid-gap sphere) where the tier
// gives mesh scales.
#include <cmath>
#include <filesystem>

#include "studies/sweep.hpp"
#include "validation/validate_evaluators.hpp"
#include "core/input_error.hpp"

namespace magfem {

namespace {

struct SweepCurve {
  std::vector<SweepRow> rows;
  double seconds = 0;
  const SweepRow& at(double angle) const {
    for (const auto& r : rows)
      if (std::abs(r.angle_deg - angle) < 1e-9) {
        if (!r.ok)
          throw std::runtime_error("sweep position " + std::to_string(angle) + " deg: " + r.error);
        return r;
      }
    throw std::runtime_error("sweep has no position " + std::to_string(angle) + " deg");
  }
};

std::string angles_key(const std::vector<double>& angles) {
  std::string k;
  for (double a : angles)
    k += std::to_string(a) + ",";
  return k;
}

// Sweep of the group `outer` about y (the thesis's tilt), cached per case, method and angles.
std::shared_ptr<const SweepCurve> sweep(const EvalContext& ctx, const std::string& file,
                                        std::vector<double> angles, double fe_scale) {
  const bool analytic = fe_scale == 0;
  const std::string key = "sweep:" + file + ":" + (analytic ? "charge" : std::to_string(fe_scale)) +
                          ":" + angles_key(angles);
  return ctx.cache.get<SweepCurve>(key, [&] {
    SweepOptions o;
    o.group = ctx.text("group", "outer");
    o.axis = Eigen::Vector3d::UnitY();
    o.angles_deg = angles;
    o.analytic = analytic;
    o.mesh_scale = fe_scale;
    o.jobs = 1; // entries already run in parallel
    // 1e-4 converges torque and force to < 1e-5 relative (tests/analytic/
    // test_charge_gravity_compensator.cpp); the default 1e-6 costs ten times more.
    o.analytic_tolerance = ctx.number("charge_tolerance", 1e-4);
    SweepCurve c;
    c.rows = run_sweep(*cached_case(ctx.cache, file), o);
    for (const auto& r : c.rows)
      c.seconds += r.seconds;
    return c;
  });
}

// The published figures of sec. 4.4 from a curve that holds the needed angles. Signs: the
// sweep gives torque and force on the outer (rotated) magnet; the thesis's attraction at
// 0 deg pulls the outer magnet down (-z), its repulsion at 60 deg pushes it up.
std::vector<double> angles_for(const std::string& q) {
  if (q == "torque_90" || q == "torque_ratio")
    return {90};
  if (q == "attraction_0")
    return {0};
  if (q == "repulsion_60")
    return {60};
  if (q == "zero_force_angle")
    return {33, 39};
  return {0, 15, 30, 45, 60, 75, 90, 105, 120, 135, 150, 165, 180}; // parasitic_torque_pct
}

double measure(const std::string& q, const SweepCurve& c) {
  if (q == "torque_90" || q == "torque_ratio")
    return std::abs(c.at(90).torque.y());
  if (q == "attraction_0")
    return -c.at(0).force.z();
  if (q == "repulsion_60")
    return c.at(60).force.z();
  if (q == "zero_force_angle") {
    // Secant between 33 and 39 deg (F_z is smooth and monotone there).
    const double fa = c.at(33).force.z(), fb = c.at(39).force.z();
    if (fa * fb > 0)
      throw std::runtime_error("F_z does not change sign between 33 and 39 deg");
    return 33 - fa * (39 - 33) / (fb - fa);
  }
  // Parasitic torque (about x and z) in % of the peak torque about the tilt axis.
  double peak = 0, parasitic = 0;
  for (const auto& r : c.rows) {
    if (!r.ok)
      throw std::runtime_error("sweep position failed: " + r.error);
    peak = std::max(peak, std::abs(r.torque.y()));
    parasitic = std::max(parasitic, std::hypot(r.torque.x(), r.torque.z()));
  }
  return 100 * parasitic / peak;
}

std::string resolve(const EvalContext& ctx, const std::string& key) {
  return (std::filesystem::path(ctx.entry.evaluate->file()).parent_path() /
          ctx.entry.evaluate->at(key).as_string())
      .lexically_normal()
      .string();
}

EvalResult compensator(const EvalContext& ctx) {
  const CatalogueEntry& e = ctx.entry;
  const std::string q = e.evaluator_quantity;
  const auto angles = angles_for(q);
  const bool ratio = q == "torque_ratio";
  const std::string ref_file = ratio ? resolve(ctx, "reference_case") : "";
  auto value = [&](double scale) {
    const double v = measure(q, *sweep(ctx, e.case_file, angles, scale));
    return ratio ? v / measure(q, *sweep(ctx, ref_file, angles, scale)) : v;
  };
  EvalResult r;
  r.analytic = value(0);
  std::vector<double> fe;
  for (double s : ctx.fe_scales()) {
    fe.push_back(value(s));
    const auto c = sweep(ctx, e.case_file, angles, s);
    long unknowns = 0;
    for (const auto& row : c->rows)
      unknowns = std::max(unknowns, row.unknowns);
    r.details["fe"].push_back({{"mesh_scale", s}, {"unknowns", unknowns},
                               {"seconds", c->seconds}, {"value", fe.back()}});
  }
  if (!fe.empty()) {
    r.fe = fe.back();
    if (fe.size() > 1)
      r.fe_coarse = fe[fe.size() - 2];
  }
  // The whole curve for the report (charge model, 15-degree steps), published points over it.
  if (ctx.text("plot", "no") != "no") {
    std::vector<double> all;
    for (int a = 0; a <= 180; a += 15)
      all.push_back(a);
    const auto curve = sweep(ctx, e.case_file, all, 0);
    PlotSeries ty{"charge model T_y on outer", {}, {}, false};
    PlotSeries fz{"charge model F_z on outer", {}, {}, false};
    for (const auto& row : curve->rows)
      if (row.ok) {
        ty.x.push_back(row.angle_deg), ty.y.push_back(row.torque.y());
        fz.x.push_back(row.angle_deg), fz.y.push_back(row.force.z());
      }
    Plot torque{"Torque about the tilt axis", "theta (deg)", "T_y (N m)", {ty}};
    Plot force{"Axial force on the outer magnet", "theta (deg)", "F_z (N)", {fz}};
    if (ctx.text("plot", "no") == "published") {
      torque.series.push_back({"published 12 N m amplitude", {90}, {12}, true});
      force.series.push_back({"published (533 N, 0 at 36 deg, 124 N)", {0, 36, 60}, {-533, 0, 124}, true});
    }
    r.plots.push_back(torque);
    r.plots.push_back(force);
  }
  r.method = "Outer magnet (group 'outer') of " + e.case_file +
             " tilted about y; torque about the centre and force on it by the charge interaction "
             "(analytic)" +
             (fe.empty() ? "" : " and by FE (Maxwell stress on a mid-gap sphere, remeshed per angle)") +
             " through magfem sweep" + (ratio ? ", divided by the same for " + ref_file : "") + ".";
  return r;
}

} // namespace

void register_thesis_ch4(std::map<std::string, Evaluator>& r) {
  r["compensator_sweep"] = {"compensator_sweep",
                            {"torque_90", "attraction_0", "repulsion_60", "zero_force_angle",
                             "parasitic_torque_pct", "torque_ratio"},
                            true,
                            compensator};
}

} // namespace magfem
