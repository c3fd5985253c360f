// Evaluator for seed 001 (Son/Song/Lee, 001_7c84ed1ea2a83d2b.txt): the DMP spherical actuator's
// design B against design A (Fig. 4). The rotor torque about y of the energized EM pair against
// the rotor's inclination about y, by the Lorentz torque in the charge model's field (the DMP
// model's own physics: magnets as magnetic charges, coils by the Lorentz law), for the two
// cases (examples/3d/dmp_actuator_{a,b}.yaml, whose headers list the assumptions); the
// quantity is the ratio of the peak torques.
#include <filesystem>

#include "app/actuator.hpp"
#include "app/validate_evaluators.hpp"

namespace magfem {

namespace {

std::shared_ptr<const InclinationTorque> curve(const EvalContext& ctx, const std::string& file) {
  return ctx.cache.get<InclinationTorque>("dmp_torque:" + file, [&] {
    return analytic_torque_about_y(*cached_case(ctx.cache, file), "rotor", 30, 2.5);
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
  r.analytic = b->peak_Nm() / a->peak_Nm();
  r.details["peak_torque_A_Nm"] = a->peak_Nm();
  r.details["peak_torque_B_Nm"] = b->peak_Nm();
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
