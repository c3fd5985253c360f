// Evaluator for seed 001 (Son/Song/Lee, 001_7c84ed1ea2a83d2b.txt): the DMP spherical actuator's
// design B against design A (Fig. 4). The rotor torque about y of the energized EM pair against
// the rotor's inclination about y, by the Lorentz torque on the coils (the DMP model's own
// physics: magnets as magnetic charges, coils by the Lorentz law), for the two cases
// (examples/3d/dmp_actuator_{a,b}.yaml, whose headers list the assumptions); the quantity is
// the ratio of the peak torques.
//
// The rotor's field is the charge model's, and in the tiers with FE scales also the FE's.
// Magnets of mu_r 1 in air make the field of the magnets turn rigidly with the rotor, so one
// FE solve of the magnets alone (the coils are left out: in linear air their own field adds
// no net torque on the pair) serves every inclination, as in `magfem actuator`
// (studies/actuator.hpp fe_rotor_field); both fields meet the same coil quadrature.
#include <chrono>
#include <filesystem>

#include "studies/actuator.hpp"
#include "pipeline/run3d.hpp"
#include "validation/validate_evaluators.hpp"

namespace magfem {

namespace {

// Fig. 4's curve: inclinations -30..30 deg in steps of 2.5 deg (the peak lies at 10-12.5 deg).
constexpr double max_inclination_deg = 30, inclination_step_deg = 2.5;

std::shared_ptr<const InclinationTorque> curve(const EvalContext& ctx, const std::string& file) {
  return ctx.cache.get<InclinationTorque>("dmp_torque:" + file, [&] {
    return analytic_torque_about_y(*cached_case(ctx.cache, file), "rotor", max_inclination_deg,
                                   inclination_step_deg);
  });
}

struct FeCurve {
  InclinationTorque torque;
  long elements = 0, unknowns = 0;
  double seconds = 0;
};

std::shared_ptr<const FeCurve> fe_curve(const EvalContext& ctx, const std::string& file,
                                        double mesh_scale) {
  return ctx.cache.get<FeCurve>("dmp_torque_fe:" + file + ":" + std::to_string(mesh_scale), [&] {
    const auto t0 = std::chrono::steady_clock::now();
    const CaseSpec& spec = *cached_case(ctx.cache, file);
    RunOverrides ov;
    ov.mesh_scale = mesh_scale;
    std::shared_ptr<const Run3D> run;
    const FieldAtPoints b = fe_rotor_field(spec, "rotor", ov, &run);
    FeCurve out;
    out.torque = torque_about_y(spec, b, max_inclination_deg, inclination_step_deg);
    out.elements = static_cast<long>(run->mesh.n_tets());
    out.unknowns = static_cast<long>(run->dofs->n_dofs());
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  });
}

nlohmann::ordered_json describe(const FeCurve& c, double mesh_scale) {
  return {{"mesh_scale", mesh_scale},
          {"peak_torque_Nm", c.torque.peak_Nm()},
          {"elements", c.elements},
          {"unknowns", c.unknowns},
          {"seconds", c.seconds}};
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
  Plot plot{"Rotor torque about y, EM pair at +2 / -2 A",
            "inclination about y (deg)",
            "T_y (N m)",
            {{"design A", a->ry_deg, a->ty_Nm, false}, {"design B", b->ry_deg, b->ty_Nm, false}}};
  r.method = "Rotor torque about y from the case's coil currents (the EM pair in the ZX plane at "
             "+2 / -2 A) at inclinations -30..30 deg about y (step 2.5 deg), minus the Lorentz "
             "torque on the coils in the charge model's field, for " +
             ctx.entry.case_file + " (B) and " + ref + " (A); the ratio of the peak |T_y|.";
  const auto scales = ctx.fe_scales();
  if (set_fe_values(r, scales, [&](double scale) {
        return fe_curve(ctx, ctx.entry.case_file, scale)->torque.peak_Nm() /
               fe_curve(ctx, ref, scale)->torque.peak_Nm();
      })) {
    r.method += " FE: the same torque in the field of one FE solve of each design's magnets "
                "(coils left out) in the rotor's frame, turned with the rotor.";
    nlohmann::ordered_json fe = nlohmann::ordered_json::array();
    for (const double s : scales)
      fe.push_back({{"design_A", describe(*fe_curve(ctx, ref, s), s)},
                    {"design_B", describe(*fe_curve(ctx, ctx.entry.case_file, s), s)}});
    r.details["fe"] = fe;
    const auto fa = fe_curve(ctx, ref, scales.back());
    const auto fb = fe_curve(ctx, ctx.entry.case_file, scales.back());
    plot.series.push_back({"design A, FE", fa->torque.ry_deg, fa->torque.ty_Nm, true});
    plot.series.push_back({"design B, FE", fb->torque.ry_deg, fb->torque.ty_Nm, true});
  }
  r.plots.push_back(plot);
  return r;
}

} // namespace

void register_dmp(std::map<std::string, Evaluator>& r) {
  r["dmp_design_ratio"] = {"dmp_design_ratio", {"peak_torque_ratio"}, true, design_ratio};
}

} // namespace magfem
