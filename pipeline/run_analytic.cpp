#include "pipeline/run_analytic.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "analytic/charge_model.hpp"
#include "analytic/harmonic_model.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "core/output_stage.hpp"
#include "mesh/symmetry_plane2d.hpp"
#include "pipeline/analytic_axi.hpp"
#include "pipeline/analytic_coils3d.hpp"
#include "pipeline/build_info.hpp"
#include "pipeline/coil_run3d.hpp"
#include "pipeline/inductance_matrix_output.hpp"
#include "pipeline/resource_usage.hpp"
#include "postproc/probe_rows3d.hpp"
#include "postproc/probes3d.hpp"

namespace magfem {
namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

using BatchField = std::function<std::vector<Eigen::Vector3d>(const std::vector<Eigen::Vector3d>&)>;

BatchField make_magnet_model(const AnalyticRun& run);

// The coils' Biot-Savart field added to the magnets' model. Coils are not imaged in
// permeable spheres (no such model here), so such cases are refused.
BatchField make_model(const AnalyticRun& run) {
  const auto& coils = run.spec.geometry3d.coils;
  if (coils.empty())
    return make_magnet_model(run);
  if (!run.scene.spheres.empty())
    throw InputError(run.spec.file, run.spec.coil_lines.front(), "coils." + coils.front().name,
                     "the analytic models do not image coils in permeable spheres or a "
                     "Dirichlet boundary; use magfem solve");
  BatchField magnets;
  if (!run.scene.magnets.empty())
    magnets = make_magnet_model(run);
  auto source = std::make_shared<CaseCoils>(coils);
  return [magnets, source](const std::vector<Eigen::Vector3d>& x) {
    std::vector<Eigen::Vector3d> b =
        magnets ? magnets(x) : std::vector<Eigen::Vector3d>(x.size(), Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < x.size(); ++i)
      b[i] += mu0 * source->H(x[i]);
    return b;
  };
}

BatchField make_magnet_model(const AnalyticRun& run) {
  if (run.options.model == "harmonic") {
    HarmonicOptions o;
    o.n_max = run.options.n_max;
    try {
      auto model = std::make_shared<HarmonicModel>(run.scene.magnets, run.scene.spheres, o);
      return [model](const std::vector<Eigen::Vector3d>& x) { return model->B(x); };
    } catch (const std::invalid_argument& e) {
      throw InputError(run.spec.file, 0, "regions", std::string("harmonic model: ") + e.what());
    }
  }
  if (run.options.model != "charge")
    throw InputError("<command line>", 0, "--model",
                     "unknown model '" + run.options.model + "' (charge, harmonic)");
  ChargeModelOptions o;
  o.tolerance = run.options.tolerance;
  try {
    auto model = std::make_shared<ChargeModel>(run.scene.magnets, run.scene.spheres, o);
    return [model](const std::vector<Eigen::Vector3d>& x) { return model->B(x); };
  } catch (const std::invalid_argument& e) {
    throw InputError(run.spec.file, 0, "regions", std::string("charge model: ") + e.what());
  }
}

} // namespace

namespace {

// The models give the field at points only; a section's flux is an FE output. Said in the
// notes (console and summary.json) rather than dropped without a word.
void note_sections_not_computed(AnalyticRun& run) {
  for (const auto& section : run.spec.sections)
    run.scene.notes.push_back("section " + section.name +
                              ": not computed by the analytic models (magfem solve writes it)");
}

// Symmetry planes tell the mesher which share of the device to mesh; the case file still
// describes the whole device, which is what the analytic models take (a plane's cut applied
// to their geometry would leave half a coil or magnet). Dropped, and said so in the notes.
CaseSpec whole_device(CaseSpec spec, std::vector<std::string>& notes) {
  std::vector<std::string> names;
  for (const SymmetryPlane3D& p : spec.geometry3d.symmetry)
    names.push_back(axis_name(p.axis));
  for (const SymmetryPlane2D& p : spec.geometry2d.planes)
    names.push_back(plane_name_2d(p, spec.axisymmetric()));
  for (const std::string& name : names)
    notes.push_back("symmetry plane " + name +
                    " = 0: used by magfem solve to mesh a share only; the analytic models "
                    "evaluate the whole device the case describes");
  spec.geometry3d.symmetry.clear();
  spec.geometry2d.planes.clear();
  return spec;
}

} // namespace

std::unique_ptr<AnalyticRun> run_case_analytic(CaseSpec spec, const AnalyticOptions& options) {
  const auto t_start = Clock::now();
  auto run = std::make_unique<AnalyticRun>();
  run->options = options;
  std::vector<std::string> plane_notes;
  spec = whole_device(std::move(spec), plane_notes);
  if (spec.axisymmetric()) {
    run->spec = std::move(spec);
    run_axi_analytic(*run);
    run->scene.notes.insert(run->scene.notes.end(), plane_notes.begin(), plane_notes.end());
    note_sections_not_computed(*run);
    run->evaluate_s = run->total_s = since(t_start);
    return run;
  }
  run->scene = analytic_scene(spec);
  run->spec = std::move(spec);
  run->scene.notes.insert(run->scene.notes.end(), plane_notes.begin(), plane_notes.end());
  note_sections_not_computed(*run);
  auto t0 = Clock::now();
  const BatchField field = make_model(*run);
  run->setup_s = since(t0);
  t0 = Clock::now();
  for (const auto& probe : run->spec.probes) {
    const auto points = probe_points_3d(probe);
    run->n_points += points.size();
    std::vector<Eigen::Vector3d> b;
    try {
      b = field(points);
    } catch (const std::domain_error& e) {
      throw InputError(run->spec.file, probe.line, "probes." + probe.name, e.what());
    }
    run->probes.push_back(tabulate_probe_3d(probe, points, b, run->spec.length_unit));
  }
  if (!run->spec.geometry3d.coils.empty()) {
    ChargeModelOptions o;
    o.tolerance = options.tolerance;
    analytic_coils_3d(*run, o);
  }
  run->evaluate_s = since(t0);
  run->sources = std::to_string(run->scene.magnets.size()) + " magnet(s) by the " + options.model +
                 " model, " + std::to_string(run->spec.geometry3d.coils.size()) +
                 " coil(s) by their source field";
  run->total_s = since(t_start);
  return run;
}

namespace {

nlohmann::ordered_json analytic_coils_json(const AnalyticRun& run) {
  nlohmann::ordered_json coils = nlohmann::ordered_json::array();
  const bool axi = run.spec.axisymmetric();
  for (std::size_t k = 0; k < run.coils.size(); ++k) {
    const CoilResult& c = run.coils[k];
    // The FE's keys: 3D adds resistance and loss.
    nlohmann::ordered_json j = {{"name", c.name}, {"turns", c.turns}, {"current_A", c.current_A}};
    if (!axi) {
      j["resistance_ohm"] = c.resistance_ohm;
      j["power_W"] = c.power_W;
    }
    const bool known = run.linkage_known[k];
    j["flux_linkage_Wb"] = known ? nlohmann::ordered_json(c.flux_linkage_Wb) : nullptr;
    // The FE's meaning: d lambda / dI (the models are linear, so the self-inductance, the
    // matrix's diagonal) and the apparent lambda / I, which counts the magnets' flux.
    const auto i = static_cast<Eigen::Index>(k);
    j["inductance_H"] =
        i < run.inductance_H.rows() ? nlohmann::ordered_json(run.inductance_H(i, i)) : nullptr;
    j["linkage_per_ampere_H"] = known && c.current_A != 0
                                    ? nlohmann::ordered_json(c.flux_linkage_Wb / c.current_A)
                                    : nullptr;
    j["force_N"] = {c.force_N.x(), c.force_N.y(), c.force_N.z()};
    if (!axi)
      j["torque_Nm"] = {c.torque_Nm.x(), c.torque_Nm.y(), c.torque_Nm.z()};
    coils.push_back(j);
  }
  return coils;
}

} // namespace

nlohmann::ordered_json summary_json_analytic(const AnalyticRun& run) {
  nlohmann::ordered_json j;
  add_provenance(j);
  j["case"] = run.spec.file;
  const bool axi = run.spec.axisymmetric();
  if (axi)
    j["dimension"] = "axi";
  else
    j["dimension"] = 3;
  j["method"] = "analytic";
  j["sources"] = run.sources;
  if (axi)
    j["model"] = "axisymmetric closed forms";
  else
    j["model"] = run.options.model;
  if (!axi && run.options.model == "charge")
    j["tolerance"] = run.options.tolerance;
  else if (!axi)
    j["n_max"] = run.options.n_max;
  if (!axi) {
    j["magnets"] = run.scene.magnets.size();
    j["permeable_spheres"] = run.scene.spheres.size();
  }
  j["points"] = run.n_points;
  j["converged"] = true;
  j["timings_s"] = {{"setup", run.setup_s}, {"evaluate", run.evaluate_s}, {"total", run.total_s}};
  j["ms_per_point"] = run.n_points ? 1e3 * run.evaluate_s / static_cast<double>(run.n_points) : 0.0;
  j["peak_memory_MB"] = peak_memory_mb();
  j["notes"] = run.scene.notes;
  for (const auto& p : run.probes)
    j["probes"].push_back(p.name + ".csv");
  if (!run.forces.empty()) {
    if (axi)
      j["forces_per"] = "body of revolution";
    j["forces"] = forces_json(run.forces);
  }
  if (!run.coils.empty())
    j["coils"] = analytic_coils_json(run);
  if (run.inductance_H.size() > 0) {
    std::vector<std::string> names;
    for (Eigen::Index i = 0; i < run.inductance_H.rows(); ++i)
      names.push_back(run.coils[static_cast<std::size_t>(i)].name);
    j["inductance_H"] = inductance_matrix_json(names, run.inductance_H);
  }
  return j;
}

std::vector<std::string> write_outputs_analytic(const AnalyticRun& run,
                                                const std::filesystem::path& out_dir) {
  std::filesystem::create_directories(out_dir);
  OutputStage stage(out_dir);
  for (const auto& p : run.probes)
    stage.write_text(p.name + ".csv", p.to_csv());
  if (!run.forces.empty())
    stage.write_text("forces.csv", forces_csv(run.forces));
  stage.write_text("summary.json", summary_json_analytic(run).dump(2) + "\n");
  stage.commit();
  return stage.written();
}

std::string describe_analytic(const AnalyticRun& run) {
  char buf[512];
  std::string s;
  if (run.spec.axisymmetric())
    s = "model    axisymmetric closed forms: " + run.sources + "\n";
  else {
    std::snprintf(buf, sizeof buf,
                  "model    %s, %zu magnets, %zu permeable sphere(s), %zu coil(s)\n",
                  run.options.model.c_str(), run.scene.magnets.size(), run.scene.spheres.size(),
                  run.spec.geometry3d.coils.size());
    s = buf;
  }
  std::snprintf(buf, sizeof buf, "points   %zu in %.3f s (%.3f ms per point), setup %.3f s\n",
                run.n_points, run.evaluate_s,
                run.n_points ? 1e3 * run.evaluate_s / static_cast<double>(run.n_points) : 0.0,
                run.setup_s);
  s += buf;
  s += describe_forces(run.forces, false);
  for (std::size_t k = 0; k < run.coils.size(); ++k) {
    const CoilResult& c = run.coils[k];
    std::snprintf(buf, sizeof buf,
                  "coil     %-12s F (%.5g, %.5g, %.5g) N, T (%.5g, %.5g, %.5g) N m, ",
                  c.name.c_str(), c.force_N.x(), c.force_N.y(), c.force_N.z(), c.torque_Nm.x(),
                  c.torque_Nm.y(), c.torque_Nm.z());
    s += buf;
    if (run.linkage_known[k] && c.current_A != 0) {
      std::snprintf(buf, sizeof buf, "linkage %.6g Wb, linkage / I = %.6g H (apparent)\n",
                    c.flux_linkage_Wb, c.flux_linkage_Wb / c.current_A);
      s += buf;
    } else if (run.linkage_known[k]) {
      std::snprintf(buf, sizeof buf, "linkage %.6g Wb\n", c.flux_linkage_Wb);
      s += buf;
    } else
      s += "linkage not computed\n";
  }
  if (run.inductance_H.rows() > 0 && run.inductance_H.rows() <= 4)
    s += "L = dlambda/dI (H, differential):\n";
  s += describe_inductance_matrix(run.inductance_H);
  for (const auto& n : run.scene.notes)
    s += "note     " + n + "\n";
  return s;
}

} // namespace magfem
