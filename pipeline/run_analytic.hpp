#pragma once
// `magfem analytic`: the same case file and probes, answered by the analytic models
// (charge model with imaging by default, spherical harmonic model on request; coils by their
// source fields, pipeline/analytic_coils3d.hpp; axisymmetric cases by pipeline/analytic_axi.hpp),
// written as the same CSVs (probes, forces.csv) and summary.json keys (coils, inductance_H),
// so FE and analytic results can be compared point by point.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <nlohmann/json.hpp>

#include "pipeline/analytic_scene.hpp"
#include "pipeline/coil_run3d.hpp"
#include "pipeline/force_results.hpp"
#include "postproc/probe_table.hpp"

namespace magfem {

struct AnalyticOptions {
  std::string model = "charge"; // charge | harmonic
  double tolerance = 1e-6;      // charge model: relative quadrature tolerance
  int n_max = 150;              // harmonic model: highest degree
};

struct AnalyticRun {
  CaseSpec spec;
  AnalyticScene scene;
  AnalyticOptions options;
  std::vector<ProbeTable> probes;
  std::vector<ForceResult> forces; // the case's force specs the models can answer
  std::vector<CoilResult> coils;   // force and torque about the origin; 3D and axi
  std::vector<bool> linkage_known; // per coil: flux_linkage_Wb was computed
  Eigen::MatrixXd inductance_H;    // coils in order; empty when not computable
  std::string sources;             // what modelled what, for the console and summary
  std::size_t n_points = 0;
  double setup_s = 0, evaluate_s = 0, total_s = 0;
};

std::unique_ptr<AnalyticRun> run_case_analytic(CaseSpec spec, const AnalyticOptions& options);
// summary.json's content (what write_outputs_analytic writes; AnalyticSolution.summary).
nlohmann::ordered_json summary_json_analytic(const AnalyticRun& run);
std::vector<std::string> write_outputs_analytic(const AnalyticRun& run,
                                                const std::filesystem::path& out_dir);
std::string describe_analytic(const AnalyticRun& run);

} // namespace magfem
