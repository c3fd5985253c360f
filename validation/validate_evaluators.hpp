#pragma once
// The evaluators of `magfem validate`: small named functions that compute one published
// figure with the analytic models (validation/) and the FE pipeline (app/run2d, run3d,
// sweep). The catalogue names an evaluator and a quantity; the registry checks both when the
// catalogue is read, so a typo is bad input (exit 2), not a failed entry.
//
// FE settings per tier come from the entry's `evaluate.fe` map: either an accuracy
// (CatalogueEntry::fe_accuracy: one adaptive solve per case, from a coarse first mesh, whose
// loop estimates the error of the named quantity), or `quick: [s_coarse, s]` and
// `full: [...]` mesh scales (RunOverrides::mesh_scale; the last one is the result, the one
// before it gives the discretisation estimate). A tier without FE computes only the
// analytic value.
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "casefile/adapt_spec.hpp"
#include "casefile/case_spec.hpp"
#include "postproc/demagnetization.hpp"
#include "postproc/probe_table.hpp"
#include "validation/validate_cache.hpp"
#include "validation/validate_catalogue.hpp"

namespace magfem {

// A line plot for the report (drawn as inline SVG).
struct PlotSeries {
  std::string name;
  std::vector<double> x, y;
  bool points_only = false; // markers (published points) instead of a line
};
struct Plot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
};

// How the adaptive solves behind an FE value ended (CatalogueEntry::fe_accuracy).
struct FeAdaptOutcome {
  double accuracy_pct = 0;
  int passes = 0;          // the most passes any of the value's solves took
  bool converged = true;   // every solve reached the accuracy
  std::string stop_reason; // why the first solve that did not stopped
  // The loop's estimate of its quantity's relative error (%), summed over the solves the
  // value combines (a ratio or difference of two solves: relative errors add, to first
  // order); NaN when a solve has none (it stopped on its first pass).
  double estimate_pct = 0;
};

struct EvalResult {
  std::optional<double> fe, analytic;
  std::optional<double> fe_coarse;        // the same quantity on the next coarser mesh
  std::optional<FeAdaptOutcome> fe_adapt; // set when the value comes from adaptive solves
  std::optional<long> fe_unknowns;        // the largest mesh the FE value used
  std::string method;                     // how magfem computes it (one or two sentences)
  nlohmann::ordered_json details = nlohmann::ordered_json::object(); // settings, sizes, extras
  std::vector<Plot> plots;
};

// One FE mesh setting: a fixed mesh scale, or an adaptive solve starting at mesh_scale.
struct FeMesh {
  double mesh_scale = 0; // 0: the case's mesh
  std::optional<AdaptSpec> adapt;
  std::string key() const; // for the cache
};

struct EvalContext {
  const CatalogueEntry& entry;
  ValidationTier tier;
  ComputeCache& cache;
  // FE mesh scales for this tier (empty: no FE in this tier, or an entry with an accuracy).
  std::vector<double> fe_scales() const;
  // The FE settings of this tier, coarse to fine: one adaptive solve for an entry with an
  // accuracy, else one per mesh scale (empty: no FE in this tier).
  std::vector<FeMesh> fe_meshes() const;
  // Parameter of evaluate (throws InputError naming the entry if missing).
  double number(const std::string& key) const;
  double number(const std::string& key, double fallback) const;
  std::string text(const std::string& key, const std::string& fallback) const;
};

struct Evaluator {
  std::string name;
  std::vector<std::string> quantities; // allowed values of evaluate.quantity
  bool needs_case = false;
  std::function<EvalResult(const EvalContext&)> run;
  bool adapts = false; // reads fe_meshes(): its entries may ask for an accuracy
};

// r.fe = value(finest scale) and r.fe_coarse = value(the next coarser one), as the FE scales
// of the tier give them; nothing when the tier has none. Returns whether FE ran.
bool set_fe_values(EvalResult& r, const std::vector<double>& scales,
                   const std::function<double(double)>& value);

// --- Shared computations (cached by case file and mesh scale) -----------------------------
// An FE run reduced to what the evaluators read: the probe tables and the run's size.
struct FeProbes {
  std::vector<ProbeTable> probes;
  std::vector<DemagnetizationCheck> demagnetization; // per magnet region (summary.json's)
  double mesh_scale = 0;                             // of the first pass for an adaptive solve
  std::optional<FeAdaptOutcome> adapt;               // an adaptive solve's outcome (its last pass)
  long elements = 0, unknowns = 0;
  int iterations = 0;
  double seconds = 0;
  const ProbeTable& probe(const std::string& name) const;
  nlohmann::ordered_json describe() const; // mesh scale, elements, unknowns, iterations, time
};
// FE solve of a 2D or 3D case on a mesh setting (adaptive: pipeline/solve_case.hpp).
std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const CaseSpec& spec,
                                          const std::string& key, const FeMesh& mesh);
std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const std::string& case_file,
                                          const FeMesh& mesh);
// The same at a fixed mesh scale (0: the case's mesh).
std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const CaseSpec& spec,
                                          const std::string& key, double mesh_scale);
std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const std::string& case_file,
                                          double mesh_scale);
// Folds one solve behind r.fe into r: its size, and its adaptive outcome (passes, whether it
// converged, its estimate added to the value's).
void record_fe_solve(EvalResult& r, const FeProbes& solve);
// The case's probes by the analytic models (model: charge | harmonic).
std::shared_ptr<const FeProbes> analytic_probes(ComputeCache& cache, const std::string& case_file,
                                                const std::string& model, double tolerance,
                                                int n_max);
// Cached case file (read once).
std::shared_ptr<const CaseSpec> cached_case(ComputeCache& cache, const std::string& case_file);

// All evaluators by name.
const std::map<std::string, Evaluator>& evaluator_registry();

// Registration per source (validate_eval_*.cpp).
void register_thesis_ch3(std::map<std::string, Evaluator>& r);
void register_thesis_ch4(std::map<std::string, Evaluator>& r);
void register_thesis_ch5(std::map<std::string, Evaluator>& r);
void register_thesis_ch6(std::map<std::string, Evaluator>& r);
void register_harwin(std::map<std::string, Evaluator>& r);
void register_voicecoil(std::map<std::string, Evaluator>& r);
void register_dmp(std::map<std::string, Evaluator>& r);
void register_demagnetization(std::map<std::string, Evaluator>& r);

} // namespace magfem
