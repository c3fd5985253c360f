// Evaluators for thesis ch. 5 (003_8d5b5c90a0e7438f.txt): the spherical actuator's topologies,
// by the charge model with spherical imaging (the thesis's own method for sec. 5.3):
// - actuator_backiron_field: the increase of the peak mid-gap B_r when back-iron is added
//   behind the magnets, or behind the magnets and the coils (sec. 5.3.3: +26 % / +80 %);
// - actuator_coil_pitch: the coil-pitch study (studies/actuator_coil_pitch.hpp): the least mean
//   loss over the pitches for one back-iron configuration (Table 5.4), or the decrease of that
//   minimum from the configuration without back-iron (Table 5.5);
// - actuator_backiron_fe: FE against the charge model with imaging at mid-gap (Fig. 5.3b);
// - actuator_segmented_backiron: the same increase by FE for the segmented back-iron of sec.
//   5.4 (+19 % at xi = 35 deg), which the charge model cannot image;
// - actuator_saturation: nonlinear FE of the back-iron at h_bm = 5 and 10 mm (sec. 5.4).
// The back-iron configurations are the case's parameters magnet_iron_mu_r and coil_iron_mu_r
// (examples/3d/spherical_actuator_topology.yaml): 1 = off, 4000 = on (imaged as mu_r -> inf).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "studies/actuator_coil_pitch.hpp"
#include "pipeline/run3d.hpp"
#include "studies/sweep.hpp"
#include "validation/validate_evaluators.hpp"
#include "core/constants.hpp"

namespace magfem {

namespace {

struct Irons {
  double magnet = 1, coil = 1;
  std::string key() const { return std::to_string(magnet) + "," + std::to_string(coil); }
  ParameterOverrides parameters() const {
    return {{"magnet_iron_mu_r", magnet}, {"coil_iron_mu_r", coil}};
  }
};

Irons irons_for(const std::string& configuration) {
  if (configuration == "none")
    return {1, 1};
  if (configuration == "magnet")
    return {4000, 1};
  return {4000, 4000}; // "magnet_and_coil"
}

// Cache key of a parameter set: name=value pairs (a map: in name order).
std::string key_of(const ParameterOverrides& parameters) {
  std::string key;
  for (const auto& [name, value] : parameters)
    key += name + "=" + std::to_string(value) + ",";
  return key;
}

// The entry's case file read once per parameter set.
std::shared_ptr<const CaseSpec> case_with(const EvalContext& ctx,
                                          const ParameterOverrides& parameters) {
  const std::string& file = ctx.entry.case_file;
  return ctx.cache.get<CaseSpec>("case:" + file + ":" + key_of(parameters),
                                 [&] { return read_case(file, parameters); });
}

std::shared_ptr<const CaseSpec> case_with(const EvalContext& ctx, const Irons& irons) {
  return case_with(ctx, irons.parameters());
}

// Peak |B_r| (tesla) over the points of the mid-gap probe r69 of an FE run.
double peak_gap_br(const FeProbes& fe) {
  const ProbeTable& p = fe.probe("r69");
  const std::size_t br = p.column("Brho");
  double peak = 0;
  for (const auto& row : p.rows)
    peak = std::max(peak, std::abs(row[br]));
  return peak;
}

// FE of the case at a parameter set without its coils (they carry no current in the
// back-iron studies: air to the solver), cached per parameters and mesh scale. With
// `meshed_as`, every part is meshed as in that parameter set (a part that is air here but
// iron there keeps the iron's gap refinement), so that the two runs share one mesh.
std::shared_ptr<const FeProbes> magnets_fe(const EvalContext& ctx,
                                           const ParameterOverrides& parameters, double mesh_scale,
                                           const ParameterOverrides& meshed_as = {}) {
  CaseSpec spec = *case_with(ctx, parameters);
  spec.geometry3d.coils.clear();
  spec.coil_lines.clear();
  std::string key = ctx.entry.case_file + ":" + key_of(parameters) + ":no_coils";
  if (!meshed_as.empty()) {
    const auto& as = case_with(ctx, meshed_as)->geometry3d.parts;
    auto& parts = spec.geometry3d.parts;
    for (std::size_t i = 0; i < parts.size() && i < as.size(); ++i)
      parts[i].air = as[i].air;
    key += ":meshed_as:" + key_of(meshed_as);
  }
  return fe_probes(ctx.cache, spec, key, mesh_scale);
}

// Peak |B_r| (tesla) of the charge model (with spherical imaging of the case's iron spheres)
// over the points of the FE run's probe r69.
double charge_model_peak_br(const CaseSpec& spec, const FeProbes& fe) {
  const ProbeTable& p = fe.probe("r69");
  const std::size_t x = p.column("x");
  std::vector<Eigen::Vector3d> points;
  for (const auto& row : p.rows)
    points.push_back(spec.length_unit * Eigen::Vector3d(row[x], row[x + 1], row[x + 2]));
  std::vector<std::string> notes;
  const auto field = analytic_rotor_field(spec, "rotor", notes)(points);
  double peak = 0;
  for (std::size_t k = 0; k < points.size(); ++k)
    peak = std::max(peak, std::abs(field[k].dot(points[k].normalized())));
  return peak;
}

// Peak |B_r| (tesla) on the sphere of radius r over the magnets' hemisphere x >= 0, 1 deg grid.
struct PeakField {
  double tesla = 0;
};

std::shared_ptr<const PeakField> peak_radial_field(const EvalContext& ctx, const Irons& irons,
                                                   double radius) {
  return ctx.cache.get<PeakField>(
      "peak_br:" + ctx.entry.case_file + ":" + irons.key() + ":" + std::to_string(radius), [&] {
        std::vector<std::string> notes;
        const auto b = analytic_rotor_field(*case_with(ctx, irons), "rotor", notes);
        std::vector<Eigen::Vector3d> points;
        for (int i = 0; i <= 180; ++i)
          for (int j = -90; j <= 90; ++j) {
            const double t = i * deg_to_rad, p = j * deg_to_rad;
            points.emplace_back(radius * std::sin(t) * std::cos(p),
                                radius * std::sin(t) * std::sin(p), radius * std::cos(t));
          }
        const auto field = b(points);
        PeakField out;
        for (std::size_t k = 0; k < points.size(); ++k)
          out.tesla = std::max(out.tesla, std::abs(field[k].dot(points[k]) / radius));
        return out;
      });
}

EvalResult backiron_field(const EvalContext& ctx) {
  const double radius = ctx.number("radius_mm") * 1e-3;
  const std::string q = ctx.entry.evaluator_quantity;
  const double none = peak_radial_field(ctx, irons_for("none"), radius)->tesla;
  const double with =
      peak_radial_field(ctx, irons_for(q == "increase_magnet" ? "magnet" : "magnet_and_coil"),
                        radius)
          ->tesla;
  EvalResult r;
  r.analytic = 100 * (with / none - 1);
  r.details["peak_B_r_without_iron_T"] = none;
  r.details["peak_B_r_with_iron_T"] = with;
  r.details["radius_mm"] = radius * 1e3;
  r.method = "Peak |B_r| on the mid-gap sphere (1 deg grid over the magnets' hemisphere) of " +
             ctx.entry.case_file +
             " by the charge model, with the back-iron as full infinitely permeable spheres "
             "(spherical imaging, four images with both), against the same without iron.";
  return r;
}

std::shared_ptr<const CoilPitchStudy> study(const EvalContext& ctx, const Irons& irons) {
  const bool full = ctx.tier == ValidationTier::full;
  const std::string pitches =
      full ? ctx.text("pitches_full", ctx.text("pitches", "")) : ctx.text("pitches", "");
  const std::string grid = full ? ctx.text("orientations_full", ctx.text("orientations", ""))
                                : ctx.text("orientations", "");
  return ctx.cache.get<CoilPitchStudy>(
      "coil_pitch:" + ctx.entry.case_file + ":" + irons.key() + ":" + pitches + ":" + grid, [&] {
        ActuatorOptions o;
        o.rotor = "rotor";
        o.analytic = true;
        return run_coil_pitch_study(*case_with(ctx, irons), o,
                                    parse_angle_list(pitches, "evaluate.pitches"),
                                    parse_orientations(grid));
      });
}

PlotSeries mean_curve(const std::string& name, const CoilPitchStudy& s) {
  PlotSeries c{name, {}, {}, false};
  for (const auto& row : s.rows)
    c.x.push_back(row.pitch_deg), c.y.push_back(row.mean_W());
  return c;
}

nlohmann::ordered_json minimum_json(const CoilPitchStudy& s) {
  const auto& m = s.minimum();
  return {{"coil_pitch_deg", m.pitch_deg},
          {"n_coils", m.n_coils},
          {"P_mean_W", m.mean_W()},
          {"P_x_W", m.P_W[0]},
          {"P_y_W", m.P_W[1]},
          {"P_z_W", m.P_W[2]},
          {"table_step_deg", s.table_step_deg},
          {"seconds", s.table_seconds + s.study_seconds}};
}

EvalResult coil_pitch(const EvalContext& ctx) {
  const std::string q = ctx.entry.evaluator_quantity;
  const std::string configuration = ctx.text("configuration", "none");
  const auto with = study(ctx, irons_for(configuration));
  EvalResult r;
  Plot plot{"Mean copper loss at 1 N m against the coil pitch",
            "coil pitch (deg)",
            "P_mean (W)",
            {mean_curve(configuration, *with)}};
  r.details["minimum"] = minimum_json(*with);
  r.details["pitches_deg"] = {with->rows.front().pitch_deg, with->rows.back().pitch_deg};
  r.details["n_orientations"] = with->n_orientations;
  if (q == "P_min") {
    r.analytic = with->minimum().mean_W();
  } else { // reduction: Table 5.5, from the minima of Table 5.4 (each at its own pitch)
    const auto none = study(ctx, irons_for("none"));
    r.analytic = 100 * (1 - with->minimum().mean_W() / none->minimum().mean_W());
    r.details["minimum_without_iron"] = minimum_json(*none);
    plot.series.push_back(mean_curve("none", *none));
  }
  r.plots.push_back(plot);
  r.method = "magfem actuator --coil-pitch on " + ctx.entry.case_file +
             " (charge model with imaging; the thesis's circular-coil array per pitch, eqs. "
             "5.5-5.7 less 10 %, 14/12/10 coils): P_x, P_y, P_z by eq. 5.4 at 1 N m averaged over "
             "the orientations, their mean minimised over the pitches" +
             (q == "P_min" ? "." : ", as a decrease from the same without back-iron.");
  return r;
}

// FE of the magnets and iron (mu_r 4000; the coils carry no current and are left out) and the
// charge model with imaging (mu_r -> infinity) on the same points of the mid-gap probe r69:
// the peak |B_r| of each.
struct GapPeaks {
  double fe_T = 0, charge_T = 0;
  long elements = 0;
  double seconds = 0;
};

std::shared_ptr<const GapPeaks> gap_peaks(const EvalContext& ctx, const Irons& irons,
                                          double mesh_scale) {
  const std::string key =
      "gap_peaks:" + ctx.entry.case_file + ":" + irons.key() + ":" + std::to_string(mesh_scale);
  return ctx.cache.get<GapPeaks>(key, [&] {
    const auto fe = magnets_fe(ctx, irons.parameters(), mesh_scale);
    GapPeaks out;
    out.fe_T = peak_gap_br(*fe);
    out.charge_T = charge_model_peak_br(*case_with(ctx, irons), *fe);
    out.elements = fe->elements;
    out.seconds = fe->seconds;
    return out;
  });
}

// sec. 5.3.3 / Fig. 5.3b: how far the FE peak gap field is from the charge model's, in %.
EvalResult backiron_fe(const EvalContext& ctx) {
  const Irons irons = irons_for(ctx.text("configuration", "magnet"));
  EvalResult r;
  r.method = "Peak |B_r| on the mid-gap probe r69 of " + ctx.entry.case_file +
             " by FE (linear iron, mu_r 4000; coils left out, they carry no current) against "
             "the charge model with spherical imaging (iron as infinitely permeable spheres) on "
             "the same points: |FE / charge model - 1|.";
  const auto scales = ctx.fe_scales();
  if (!set_fe_values(r, scales, [&](double scale) {
        const auto g = gap_peaks(ctx, irons, scale);
        return 100 * std::abs(g->fe_T / g->charge_T - 1);
      }))
    return r;
  const auto g = gap_peaks(ctx, irons, scales.back());
  r.details["peak_B_r_fe_T"] = g->fe_T;
  r.details["peak_B_r_charge_model_T"] = g->charge_T;
  r.details["elements"] = g->elements;
  r.details["seconds"] = g->seconds;
  r.details["mesh_scale"] = scales.back();
  return r;
}

// sec. 5.4: the increase of the peak mid-gap |B_r| from the back-iron segments of size xi
// (examples/3d/spherical_actuator_segmented.yaml), in %: FE with the segments as iron (mu_r
// 4000) against FE with them as air on the same mesh (the iron's gap refinement kept), so
// that the discretisation error of the probe largely cancels in the ratio.
EvalResult segmented_backiron(const EvalContext& ctx) {
  const double xi = ctx.number("xi");
  const ParameterOverrides iron{{"xi", xi}, {"iron_mu_r", 4000}}, air{{"xi", xi}, {"iron_mu_r", 1}};
  auto with = [&](double scale) { return magnets_fe(ctx, iron, scale); };
  auto without = [&](double scale) { return magnets_fe(ctx, air, scale, iron); };
  EvalResult r;
  r.method = "Peak |B_r| on the mid-gap probe r69 of " + ctx.entry.case_file +
             " by FE, with back-iron segments of xi = " + std::to_string(static_cast<int>(xi)) +
             " deg (each magnet's cell shrunk to xi / 45 about its centre; linear iron, mu_r "
             "4000) against the segments as air on the same mesh.";
  const auto scales = ctx.fe_scales();
  if (!set_fe_values(r, scales, [&](double scale) {
        return 100 * (peak_gap_br(*with(scale)) / peak_gap_br(*without(scale)) - 1);
      }))
    return r;
  const auto fe_with = with(scales.back()), fe_without = without(scales.back());
  r.details["xi_deg"] = xi;
  r.details["peak_B_r_with_iron_T"] = peak_gap_br(*fe_with);
  r.details["peak_B_r_without_iron_T"] = peak_gap_br(*fe_without);
  // Without iron the charge model is exact: how far the shared mesh is from it at the probe.
  r.details["peak_B_r_without_iron_charge_model_T"] =
      charge_model_peak_br(*case_with(ctx, air), *fe_without);
  r.details["fe_with_iron"] = fe_with->describe();
  r.details["fe_without_iron"] = fe_without->describe();
  return r;
}

// One nonlinear FE solve of the saturation case at a back-iron height: the peak |B| in the
// iron and the peak |B_r| on the gap probe r69.
struct SaturationRun {
  double iron_peak_T = 0, gap_peak_T = 0;
  long elements = 0;
  int newton_steps = 0;
  double seconds = 0;
};

std::shared_ptr<const SaturationRun> saturation_run(const EvalContext& ctx, double h_bm_mm,
                                                    double mesh_scale) {
  const std::string& file = ctx.entry.case_file;
  const std::string key =
      "saturation:" + file + ":" + std::to_string(h_bm_mm) + ":" + std::to_string(mesh_scale);
  return ctx.cache.get<SaturationRun>(key, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    CaseSpec spec = read_case(file, {{"h_bm", h_bm_mm}});
    spec.write_vtu = false;
    RunOverrides ov;
    ov.mesh_scale = mesh_scale;
    const auto run = run_case_3d(std::move(spec), ov);
    SaturationRun out;
    for (const auto& region : run->energy.regions)
      if (region.nonlinear)
        out.iron_peak_T = std::max(out.iron_peak_T, region.peak_B_T);
    for (const ProbeTable& p : run->probes)
      if (p.name == "r69") {
        const std::size_t br = p.column("Brho");
        for (const auto& row : p.rows)
          out.gap_peak_T = std::max(out.gap_peak_T, std::abs(row[br]));
      }
    out.elements = static_cast<long>(run->mesh.n_tets());
    out.newton_steps = run->report.iterations;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  });
}

// sec. 5.4: peak |B| in a 5 mm (thin) or 10 mm (thick) back-iron, and how much lower the peak
// gap field is on the thin one, in % of the thick one's.
double saturation_quantity(const std::string& q, const SaturationRun& thin,
                           const SaturationRun& thick) {
  if (q == "peak_B_thin")
    return thin.iron_peak_T;
  if (q == "peak_B_thick")
    return thick.iron_peak_T;
  return 100 * (1 - thin.gap_peak_T / thick.gap_peak_T); // gap_field_difference
}

EvalResult saturation(const EvalContext& ctx) {
  const std::string q = ctx.entry.evaluator_quantity;
  EvalResult r;
  r.method = "Nonlinear FE (Newton) of " + ctx.entry.case_file +
             ": the design's magnet array on a full shell of steel_1010 behind the magnets, "
             "h_bm = 5 and 10 mm; peak |B| over the iron's nodes and peak |B_r| on the r69 "
             "probe (69 mm, over the magnets' hemisphere).";
  const auto scales = ctx.fe_scales();
  if (!set_fe_values(r, scales, [&](double scale) {
        return saturation_quantity(q, *saturation_run(ctx, 5, scale),
                                   *saturation_run(ctx, 10, scale));
      }))
    return r;
  for (double h : {5.0, 10.0}) {
    const auto run = saturation_run(ctx, h, scales.back());
    r.details["h_bm_" + std::to_string(static_cast<int>(h)) + "mm"] = {
        {"iron_peak_B_T", run->iron_peak_T},
        {"gap_peak_B_r_T", run->gap_peak_T},
        {"elements", run->elements},
        {"newton_steps", run->newton_steps},
        {"seconds", run->seconds}};
  }
  r.details["mesh_scale"] = scales.back();
  return r;
}

} // namespace

void register_thesis_ch5(std::map<std::string, Evaluator>& r) {
  r["actuator_backiron_field"] = {"actuator_backiron_field",
                                  {"increase_magnet", "increase_magnet_and_coil"},
                                  true,
                                  backiron_field};
  r["actuator_coil_pitch"] = {"actuator_coil_pitch", {"P_min", "reduction"}, true, coil_pitch};
  r["actuator_backiron_fe"] = {"actuator_backiron_fe", {"fe_vs_charge_model"}, true, backiron_fe};
  r["actuator_segmented_backiron"] = {
      "actuator_segmented_backiron", {"increase"}, true, segmented_backiron};
  r["actuator_saturation"] = {"actuator_saturation",
                              {"peak_B_thin", "peak_B_thick", "gap_field_difference"},
                              true,
                              saturation};
}

} // namespace magfem
