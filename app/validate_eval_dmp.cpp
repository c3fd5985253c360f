// Evaluator for seed 001 (Son/Song/Lee, 001_7c84ed1ea2a83d2b.txt): the DMP spherical actuator's
// design B against design A (Fig. 4). The rotor torque about y of the energized EM pair against
// the rotor's inclination about y, by the Lorentz torque in the charge model's field (the DMP
// model's own physics: magnets as magnetic charges, coils by the Lorentz law), for the two
// cases (examples/3d/dmp_actuator_{a,b}.yaml, whose headers list the assumptions); the
// quantity is the ratio of the peak torques.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "app/actuator.hpp"
#include "app/validate_evaluators.hpp"

namespace magfem {

namespace {

struct TorqueCurve {
  std::vector<double> ry_deg, ty_Nm;
  double peak() const {
    double p = 0;
    for (double t : ty_Nm)
      p = std::max(p, std::abs(t));
    return p;
  }
};

std::shared_ptr<const TorqueCurve> curve(const EvalContext& ctx, const std::string& file) {
  return ctx.cache.get<TorqueCurve>("dmp_torque:" + file, [&] {
    TorqueCurve c;
    std::vector<Orientation> grid;
    for (int i = -12; i <= 12; ++i) {
      c.ry_deg.push_back(2.5 * i);
      grid.push_back({0, 2.5 * i, 0});
    }
    for (const auto& t : analytic_rotor_torque(*cached_case(ctx.cache, file), "rotor", grid))
      c.ty_Nm.push_back(t.y());
    return c;
  });
}

EvalResult design_ratio(const EvalContext& ctx) {
  const std::string ref = (std::filesystem::path(ctx.entry.evaluate->file()).parent_path() /
                           ctx.entry.evaluate->at("reference_case").as_string())
                              .lexically_normal()
                              .string();
  const auto b = curve(ctx, ctx.entry.case_file);
  const auto a = curve(ctx, ref);
  EvalResult r;
  r.analytic = b->peak() / a->peak();
  r.details["peak_torque_A_Nm"] = a->peak();
  r.details["peak_torque_B_Nm"] = b->peak();
  r.plots.push_back(
      {"Rotor torque about y, EM pair at +2 / -2 A",
       "inclination about y (deg)",
       "T_y (N m)",
       {{"design A", a->ry_deg, a->ty_Nm, false}, {"design B", b->ry_deg, b->ty_Nm, false}}});
  r.method = "Rotor torque about y from the case's coil currents (the EM pair in the ZX plane at "
             "+2 / -2 A) at inclinations -30..30 deg about y, Lorentz torque in the charge "
             "model's field, for " +
             ctx.entry.case_file + " (B) and " + ref + " (A); the ratio of the peak |T_y|.";
  return r;
}

} // namespace

void register_dmp(std::map<std::string, Evaluator>& r) {
  r["dmp_design_ratio"] = {"dmp_design_ratio", {"peak_torque_ratio"}, true, design_ratio};
}

} // namespace magfem
