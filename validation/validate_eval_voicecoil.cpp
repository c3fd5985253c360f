// Evaluators for the voice-coil paper (002_5cbab31495bf2c6b.txt, Lee / Son): Table 1 (error of
// the equivalent single layer, ESL, of a coil of fixed volume), the ESL radii and sheet
// currents of the same table, and Fig. 5 (torque between a cylinder magnet on the rotor of the
// paper's spherical motor and a stator coil). Every figure twice where it matters: with the
// paper's own 2D line model (analytic/voice_coil_line_model.hpp) and with the exact fields
// of the coil's loops (analytic/coaxial_coil_field.hpp).
#include <cmath>
#include <string>

#include "pipeline/run2d.hpp"
#include "validation/validate_evaluators.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "analytic/coaxial_coil_field.hpp"
#include "analytic/equivalent_single_layer.hpp"
#include "analytic/radial_l1_difference.hpp"
#include "analytic/rotor_coil_pair.hpp"
#include "analytic/voice_coil_line_model.hpp"

namespace magfem {

namespace {

// Table 1: wire volume 5.41 cm^3, l = 25.4 mm, 4 A; per row a_i / a_o, the printed a_e / a_o
// and sheet current J_e d_w (A/m).
constexpr double table_length = 25.4e-3, table_volume = 5.41e-6, table_current = 4.0;
struct Table1Row {
  double ratio, ae_over_ao, sheet_current;
};
constexpr Table1Row table1_rows[] = {
    {0.1, 0.582, 137.1e3}, {0.5, 0.766, 136.7e3}, {0.9, 0.951, 136.2e3}};

const Table1Row& table1_row(const EvalContext& ctx) {
  const double ratio = ctx.number("ratio");
  for (const auto& r : table1_rows)
    if (std::abs(r.ratio - ratio) < 1e-9)
      return r;
  throw InputError(ctx.entry.evaluate->file(), ctx.entry.line, "evaluate.ratio",
                   "entry '" + ctx.entry.id + "': Table 1 has the ratios 0.1, 0.5 and 0.9");
}

// The coil of a row: fixed volume pi (a_o^2 - a_i^2) l, centred on z = 0, with `per_length`
// ampere-turns per metre of its length (turns for the table's 4 A).
CoaxialCoil table1_coil(double ratio, double per_length) {
  const double ao = std::sqrt(table_volume / (pi * table_length * (1 - ratio * ratio)));
  return {ratio * ao, ao, -0.5 * table_length, 0.5 * table_length,
          per_length * table_length / table_current};
}

// The coil's ampere-turns per metre that eq. 6 needs to give a row's printed sheet current at
// its printed a_e (the error measure is a ratio and does not depend on it; the table does not
// say how its 29 AWG wire fills the winding).
double implied_per_length(const Table1Row& r) {
  const CoaxialCoil unit = table1_coil(r.ratio, table_current / table_length); // 1 A-turn / l
  const double k =
      esl_line_model_at(unit, table_current, r.ae_over_ao * unit.r_outer).sheet_current;
  return r.sheet_current / k * (table_current / table_length);
}

// Table 1's error for one row at distance eps beyond the end face, integrated over
// 0 <= y <= range (<= 0: the whole face), with the ESL of the printed a_e and eq. 6.
double table1_error(const Table1Row& r, bool exact, double eps, double range) {
  const CoaxialCoil coil = table1_coil(r.ratio, implied_per_length(r));
  const EquivalentSingleLayer esl =
      esl_line_model_at(coil, table_current, r.ae_over_ao * coil.r_outer);
  const CoaxialCoil sheet = esl.as_sheet(coil);
  const double z = coil.z_max + eps;
  const std::vector<double> breaks{coil.r_inner, coil.r_outer, esl.radius};
  if (!exact)
    return radial_l1_difference([&](double y) { return line_model_Bz(coil, table_current, y, z); },
                                [&](double y) { return line_model_Bz(sheet, 1.0, y, z); }, breaks,
                                range, 1e-3 * eps)
        .percent();
  const CoaxialCoilField ml(coil, table_current), sl(sheet, 1.0);
  return radial_l1_difference([&](double y) { return ml.Bz(y, z); },
                              [&](double y) { return sl.Bz(y, z); }, breaks, range, 1e-3 * eps)
      .percent();
}

EvalResult table1_errors(const EvalContext& ctx) {
  const Table1Row& row = table1_row(ctx);
  const bool exact = ctx.entry.evaluator_quantity == "error_exact";
  const double eps = ctx.number("epsilon_um") * 1e-6;
  const double range_l = ctx.number("range_l", 0);
  EvalResult res;
  res.analytic = table1_error(row, exact, eps, range_l * table_length);
  nlohmann::ordered_json by_range = nlohmann::ordered_json::object();
  for (double k : {1.0, 2.0, 3.0, 5.0, 10.0})
    by_range[std::to_string(int(k)) + "_l"] = table1_error(row, exact, eps, k * table_length);
  by_range["whole_face"] = table1_error(row, exact, eps, 0);
  const CoaxialCoil coil = table1_coil(row.ratio, implied_per_length(row));
  res.details = {{"a_i_mm", coil.r_inner * 1e3},
                 {"a_o_mm", coil.r_outer * 1e3},
                 {"a_e_mm", row.ae_over_ao * coil.r_outer * 1e3},
                 {"sheet_current_A_per_mm", row.sheet_current * 1e-3},
                 {"coil_ampere_turns_per_mm", implied_per_length(row) * 1e-3},
                 {"error_pct_by_range", by_range}};
  res.method =
      std::string("%Error = 100 int |B_z,ML - B_z,ESL| dy / int |B_z,ML| dy on the line ") +
      "z = l/2 + eps, 0 <= y <= " +
      (range_l > 0 ? std::to_string(range_l).substr(0, 3) + " l" : "infinity") +
      ", with the table's a_e and eq.-6 sheet current; fields by " +
      (exact ? "the exact loops of the coil and of the sheet (3D)"
             : "the paper's 2D line model (eqs. 4a, 4b, closed form)") +
      ". The integration range is not printed: details give 1 .. 10 l and the whole face.";
  if (ctx.number("plot", 0) != 0) {
    Plot p{
        "Table 1 error vs integration range, eps = " + std::to_string(int(std::lround(eps * 1e6))) +
            " um (" + (exact ? "exact fields" : "paper's 2D model") + ")",
        "range (multiples of l = 25.4 mm)",
        "%Error",
        {}};
    for (const auto& r : table1_rows) {
      PlotSeries s{"a_i/a_o = " + std::to_string(r.ratio).substr(0, 3), {}, {}, false};
      for (double k : {0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0, 10.0})
        s.x.push_back(k), s.y.push_back(table1_error(r, exact, eps, k * table_length));
      p.series.push_back(s);
    }
    const double published[2][3] = {{32.0, 13.4, 1.3}, {19.0, 6.6, 0.6}};
    PlotSeries pub{"Table 1 (range not printed)", {}, {}, true};
    for (int i = 0; i < 3; ++i)
      for (double k : {0.5, 10.0})
        pub.x.push_back(k), pub.y.push_back(published[eps < 1e-4 ? 0 : 1][i]);
    p.series.push_back(pub);
    res.plots.push_back(p);
  }
  return res;
}

// Condition I's a_e / a_o for a row (the whole end face unless range_l).
EvalResult table1_radius(const EvalContext& ctx) {
  const Table1Row& row = table1_row(ctx);
  const bool exact = ctx.entry.evaluator_quantity == "exact";
  const CoaxialCoil coil = table1_coil(row.ratio, implied_per_length(row));
  const double range = ctx.number("range_l", 0) * table_length;
  const double a =
      exact ? esl_exact(coil, table_current, range).radius : line_model_esl_radius(coil, range);
  EvalResult res;
  res.analytic = a / coil.r_outer;
  res.details = {
      {"a_e_mm", a * 1e3},
      {"mean_radius_over_a_o", 0.5 * (1 + row.ratio)},
      {exact ? "a_e_over_a_o_line_model" : "a_e_over_a_o_exact",
       (exact ? line_model_esl_radius(coil, range) : esl_exact(coil, table_current, range).radius) /
           coil.r_outer},
      {"a_e_over_a_o_line_model_range_1l",
       line_model_esl_radius(coil, table_length) / coil.r_outer}};
  res.method =
      std::string("Condition I (eq. 5): the a_e minimizing int |B_z,ML - B_z,ESL| dy over ") +
      "the end face, with eq. 6's sheet current at every trial a_e; fields by " +
      (exact ? "the exact loops (condition II with the exact end-centre field)"
             : "the paper's 2D line model") +
      "; golden-section search.";
  return res;
}

// Eq. 6's sheet current of a row from the coil current per length implied by another row.
EvalResult table1_sheet_current(const EvalContext& ctx) {
  const Table1Row& row = table1_row(ctx);
  const double from = ctx.number("calibration_ratio");
  const Table1Row* cal = nullptr;
  for (const auto& r : table1_rows)
    if (std::abs(r.ratio - from) < 1e-9)
      cal = &r;
  if (!cal)
    throw InputError(ctx.entry.evaluate->file(), ctx.entry.line, "evaluate.calibration_ratio",
                     "entry '" + ctx.entry.id + "': not a Table 1 ratio");
  const double per_length = implied_per_length(*cal);
  const CoaxialCoil coil = table1_coil(row.ratio, per_length);
  EvalResult res;
  res.analytic =
      esl_line_model_at(coil, table_current, row.ae_over_ao * coil.r_outer).sheet_current * 1e-3;
  res.details = {{"coil_ampere_turns_per_mm", per_length * 1e-3},
                 {"turns_at_4A", per_length * table_length / table_current},
                 {"implied_by_this_row_A_per_mm", implied_per_length(row) * 1e-3}};
  res.method = "Eq. 6 at the printed a_e with the coil's ampere-turns per length implied by the "
               "row a_i/a_o = " +
               std::to_string(from).substr(0, 3) +
               " (the table does not give the winding's current density; the same value must "
               "explain every row).";
  return res;
}

// Fig. 5: torque about the rotor centre versus separation angle.
std::vector<double> torque_curve(const RotorCoilPair& p, const CoaxialCoil& model, double current,
                                 const std::vector<double>& degrees) {
  std::vector<double> t;
  for (double d : degrees)
    t.push_back(magnet_wrench(p, model, current, d * deg_to_rad).torque.y());
  return t;
}

// Peak of |T(theta)| from the curve on `degrees` (a grid), refined by golden section to 0.01 deg
// around the best node.
std::pair<double, double> peak_torque(const RotorCoilPair& p, const CoaxialCoil& model,
                                      double current, const std::vector<double>& degrees,
                                      const std::vector<double>& curve) {
  auto f = [&](double d) {
    return std::abs(magnet_wrench(p, model, current, d * deg_to_rad).torque.y());
  };
  std::size_t best = 0;
  for (std::size_t i = 0; i < curve.size(); ++i)
    if (std::abs(curve[i]) > std::abs(curve[best]))
      best = i;
  double lo = degrees[best > 0 ? best - 1 : 0], hi = degrees[std::min(best + 1, curve.size() - 1)];
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  double c = hi - g * (hi - lo), d = lo + g * (hi - lo), fc = f(c), fd = f(d);
  while (hi - lo > 0.01) {
    if (fc > fd)
      hi = d, d = c, fd = fc, c = hi - g * (hi - lo), fc = f(c);
    else
      lo = c, c = d, fc = fd, d = lo + g * (hi - lo), fd = f(d);
  }
  const double at = 0.5 * (lo + hi);
  return {at, f(at)};
}

EvalResult fig5(const EvalContext& ctx) {
  RotorCoilPair p;
  p.rotor_radius = ctx.number("rotor_radius_mm", 37.5) * 1e-3;
  const double l = p.coil.z_max - p.coil.z_min;
  // The ESLs in the coil's frame: the paper's (2D conditions) and the exact-field one, which is
  // also the equivalent magnet of eq. 12 (equivalent_single_layer.hpp).
  const CoaxialCoil centred{p.coil.r_inner, p.coil.r_outer, -0.5 * l, 0.5 * l, p.coil.turns};
  const EquivalentSingleLayer esl2 = esl_line_model(centred, p.current, 0.0);
  const EquivalentSingleLayer esl3 = esl_exact(centred, p.current, 0.0);
  const CoaxialCoil s2 = esl2.as_sheet(p.coil), s3 = esl3.as_sheet(p.coil);
  std::vector<double> deg;
  for (double d = 0; d <= 60; d += 2)
    deg.push_back(d);
  const std::vector<double> ml = torque_curve(p, p.coil, p.current, deg);
  const std::vector<double> t2 = torque_curve(p, s2, 1.0, deg);
  const std::vector<double> t3 = torque_curve(p, s3, 1.0, deg);
  const auto [ml_at, ml_peak] = peak_torque(p, p.coil, p.current, deg, ml);
  const auto [e2_at, e2_peak] = peak_torque(p, s2, 1.0, deg, t2);
  const auto [e3_at, e3_peak] = peak_torque(p, s3, 1.0, deg, t3);
  double worst = 0;
  for (std::size_t i = 0; i < deg.size(); ++i)
    worst = std::max(worst, std::abs(t2[i] - ml[i]));
  EvalResult res;
  res.analytic = ml_peak;
  const double f0 = magnet_wrench(p, p.coil, p.current, 0).force.z();
  res.details = {{"rotor_radius_mm", p.rotor_radius * 1e3},
                 {"peak_angle_deg_multilayer", ml_at},
                 {"peak_torque_Nm_esl_line_model", e2_peak},
                 {"peak_angle_deg_esl_line_model", e2_at},
                 {"esl_line_model_a_e_mm", esl2.radius * 1e3},
                 {"esl_line_model_sheet_current_A_per_mm", esl2.sheet_current * 1e-3},
                 {"peak_torque_Nm_esl_exact_equivalent_magnet", e3_peak},
                 {"esl_exact_a_e_mm", esl3.radius * 1e3},
                 {"esl_exact_mu0_M_T", mu0 * esl3.sheet_current},
                 {"axial_force_on_magnet_0deg_N", f0},
                 {"max_esl_line_model_minus_multilayer_pct_of_peak", 100 * worst / ml_peak}};
  // The axial force at 0 deg by the axisymmetric FE (examples/axi/voice_coil_magnet.yaml, the
  // same pair): the Lorentz force on the coil is the reaction.
  if (!ctx.entry.case_file.empty()) {
    CaseSpec spec = *cached_case(ctx.cache, ctx.entry.case_file);
    spec.write_vtu = false;
    const auto run = run_case_2d(std::move(spec));
    for (const auto& fr : run->forces)
      if (fr.name == "coil_lorentz") {
        res.details["axial_force_on_coil_0deg_axi_fe_N"] = fr.force.z();
        res.details["axi_fe_vs_analytic_rel"] = (-fr.force.z() - f0) / f0;
      }
  }
  Plot plot{"Fig. 5: torque on the magnet about the rotor centre (rotor radius " +
                std::to_string(p.rotor_radius * 1e3).substr(0, 4) + " mm)",
            "separation angle (deg)",
            "|T_y| (N m)",
            {}};
  auto add = [&](const std::string& name, const std::vector<double>& t) {
    PlotSeries s{name, deg, t, false};
    for (double& v : s.y)
      v = std::abs(v);
    plot.series.push_back(s);
  };
  add("multilayer (exact loops)", ml);
  add("ESL, paper's conditions (2D)", t2);
  add("ESL, exact conditions = equivalent magnet", t3);
  plot.series.push_back({"paper: top of the plot (0.14 N m)", {ml_at}, {0.14}, true});
  res.plots.push_back(plot);
  res.method = "Lorentz force on the magnet's surface current (mu_r 1: K = M on its side) in the "
               "field of the coil by its exact loops, the paper's ESL and the exact-field ESL "
               "(= eq. 12's equivalent magnet); the magnet's outer face on the rotor sphere "
               "(Table 4: rotor radius 37.5 mm, air gap 0.5 mm), turning about the rotor centre; "
               "value: the peak over 0-60 deg. Axial force at 0 deg by the axisymmetric FE in "
               "the details.";
  return res;
}

// Fig. 6 / Table 2: the ESL radius of the experiment's coil under an assumed reading of Fig. 6's
// unnamed dimensions (r_inner, r_outer, length from the entry), paper's 2D conditions.
EvalResult table2_radius(const EvalContext& ctx) {
  const double ri = ctx.number("r_inner_mm") * 1e-3, ro = ctx.number("r_outer_mm") * 1e-3;
  const double length = ctx.number("length_mm") * 1e-3;
  const double turns = 280, current = 0.05;
  const CoaxialCoil coil{ri, ro, -0.5 * length, 0.5 * length, turns};
  const EquivalentSingleLayer e2 = esl_line_model(coil, current, 0.0);
  const EquivalentSingleLayer e3 = esl_exact(coil, current, 0.0);
  EvalResult res;
  res.analytic = e2.radius * 1e3;
  res.details = {{"a_e_mm_exact", e3.radius * 1e3},
                 {"sheet_current_A_per_m_line_model", e2.sheet_current},
                 {"sheet_current_A_per_m_exact", e3.sheet_current},
                 {"coil_ampere_turns_per_m", turns * current / length},
                 {"wire_length_m_from_mean_radius", turns * pi * (ri + ro)}};
  res.method = "Condition I and eq. 6 in the paper's 2D model (whole end face) for the coil of "
               "280 turns at 0.05 A with the dimensions assumed in the entry; the exact-field ESL "
               "in the details.";
  return res;
}

} // namespace

void register_voicecoil(std::map<std::string, Evaluator>& r) {
  r["voicecoil_table1"] = {
      "voicecoil_table1", {"error_line_model", "error_exact"}, false, table1_errors};
  r["voicecoil_esl_radius"] = {
      "voicecoil_esl_radius", {"line_model", "exact"}, false, table1_radius};
  r["voicecoil_sheet_current"] = {"voicecoil_sheet_current", {}, false, table1_sheet_current};
  r["voicecoil_fig5"] = {"voicecoil_fig5", {}, false, fig5};
  r["voicecoil_table2"] = {"voicecoil_table2", {}, false, table2_radius};
}

} // namespace magfem
