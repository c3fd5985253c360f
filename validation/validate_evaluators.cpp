#include "validation/validate_evaluators.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "core/input_error.hpp"
#include "pipeline/run_analytic.hpp"
#include "pipeline/solve_case.hpp"

namespace magfem {

namespace {
using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
} // namespace

std::vector<double> EvalContext::fe_scales() const {
  if (!entry.evaluate)
    return {};
  const auto fe = entry.evaluate->find("fe");
  if (!fe)
    return {};
  const auto t = fe->find(to_string(tier));
  if (!t)
    return {};
  return t->as_doubles();
}

std::vector<FeMesh> EvalContext::fe_meshes() const {
  if (entry.fe_accuracy) {
    const FeAccuracy& a = *entry.fe_accuracy;
    if (a.pct(tier) <= 0)
      return {};
    AdaptSpec spec;
    spec.accuracy_pct = a.pct(tier);
    spec.quantities = {a.quantity};
    spec.max_passes = a.max_passes;
    spec.max_unknowns = a.max_unknowns;
    return {FeMesh{a.start_scale, spec}};
  }
  std::vector<FeMesh> out;
  for (double s : fe_scales())
    out.push_back(FeMesh{s, std::nullopt});
  return out;
}

std::string FeMesh::key() const {
  char buf[160];
  if (!adapt)
    return std::to_string(mesh_scale);
  std::snprintf(buf, sizeof buf,
                "adapt %g %% from %g, %d passes, %g unknowns: ", adapt->accuracy_pct, mesh_scale,
                adapt->max_passes, adapt->max_unknowns);
  return buf + adapt->quantities.front();
}

void record_fe_solve(EvalResult& r, const FeProbes& solve) {
  r.fe_unknowns = std::max(r.fe_unknowns.value_or(0), solve.unknowns);
  if (!solve.adapt)
    return;
  const FeAdaptOutcome& s = *solve.adapt;
  if (!r.fe_adapt) {
    r.fe_adapt = s;
    return;
  }
  FeAdaptOutcome& a = *r.fe_adapt;
  a.passes = std::max(a.passes, s.passes);
  if (a.converged && !s.converged)
    a.stop_reason = s.stop_reason;
  a.converged = a.converged && s.converged;
  a.estimate_pct += s.estimate_pct;
}

bool set_fe_values(EvalResult& r, const std::vector<double>& scales,
                   const std::function<double(double)>& value) {
  if (scales.empty())
    return false;
  r.fe = value(scales.back());
  if (scales.size() > 1)
    r.fe_coarse = value(scales[scales.size() - 2]);
  return true;
}

double EvalContext::number(const std::string& key) const {
  if (!entry.evaluate || !entry.evaluate->has(key))
    throw InputError(entry.evaluate ? entry.evaluate->file() : "", entry.line, "evaluate." + key,
                     "entry '" + entry.id + "': missing parameter");
  return entry.evaluate->at(key).as_double();
}

double EvalContext::number(const std::string& key, double fallback) const {
  return entry.evaluate ? entry.evaluate->get_double(key, fallback) : fallback;
}

std::string EvalContext::text(const std::string& key, const std::string& fallback) const {
  return entry.evaluate ? entry.evaluate->get_string(key, fallback) : fallback;
}

const ProbeTable& FeProbes::probe(const std::string& name) const {
  for (const auto& p : probes)
    if (p.name == name)
      return p;
  throw std::runtime_error("no probe '" + name + "' in the case");
}

nlohmann::ordered_json FeProbes::describe() const {
  nlohmann::ordered_json d = {{"mesh_scale", mesh_scale},
                              {"elements", elements},
                              {"unknowns", unknowns},
                              {"iterations", iterations},
                              {"seconds", seconds}};
  if (adapt) {
    d["adapt"] = {{"accuracy_pct", adapt->accuracy_pct},
                  {"passes", adapt->passes},
                  {"converged", adapt->converged},
                  {"estimated_error_pct", number_or_null(adapt->estimate_pct)}};
    if (!adapt->converged)
      d["adapt"]["stop_reason"] = adapt->stop_reason;
  }
  return d;
}

std::shared_ptr<const CaseSpec> cached_case(ComputeCache& cache, const std::string& case_file) {
  return cache.get<CaseSpec>("case:" + case_file, [&] { return read_case(case_file); });
}

namespace {

// The outcome of an adaptive solve from its history: the named quantity's estimate at the
// last pass (the loop's extrapolation from the passes, adapt_loop.hpp).
FeAdaptOutcome adapt_outcome(const AdaptHistory& h) {
  FeAdaptOutcome o;
  o.accuracy_pct = h.accuracy_pct;
  o.passes = static_cast<int>(h.passes.size());
  o.converged = h.converged;
  o.stop_reason = h.stop_reason;
  const AdaptPass& last = h.passes.back();
  o.estimate_pct =
      last.quantity_error_pct.empty() ? last.energy_error_pct : last.quantity_error_pct.front();
  return o;
}

template <class Run> void take_run(FeProbes& out, const Run& run, long elements) {
  out.probes = run.probes;
  out.demagnetization = run.demagnetization.magnets;
  out.elements = elements;
  out.unknowns = static_cast<long>(run.dofs->n_dofs());
  out.iterations = run.report.iterations;
  if (run.adapt)
    out.adapt = adapt_outcome(*run.adapt);
}

} // namespace

std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const CaseSpec& spec,
                                          const std::string& key, const FeMesh& mesh) {
  return cache.get<FeProbes>("fe:" + key + ":" + mesh.key(), [&] {
    const auto t0 = Clock::now();
    RunOverrides ov;
    ov.mesh_scale = mesh.mesh_scale;
    FeProbes out;
    out.mesh_scale = mesh.mesh_scale;
    CaseSpec copy = spec;
    copy.write_vtu = false;
    // The entry's accuracy replaces whatever adapt: the case has (a case's own adapt: would
    // otherwise make a fixed-scale entry adaptive behind the catalogue's back).
    copy.adapt = mesh.adapt.value_or(AdaptSpec{});
    if (spec.dimension == 3) {
      const auto run = solve_case_3d(std::move(copy), ov);
      take_run(out, *run, static_cast<long>(run->mesh.n_tets()));
    } else {
      const auto run = solve_case_2d(std::move(copy), ov);
      take_run(out, *run, static_cast<long>(run->mesh.n_triangles()));
    }
    out.seconds = since(t0);
    return out;
  });
}

std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const std::string& case_file,
                                          const FeMesh& mesh) {
  return fe_probes(cache, *cached_case(cache, case_file), case_file, mesh);
}

std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const CaseSpec& spec,
                                          const std::string& key, double mesh_scale) {
  return fe_probes(cache, spec, key, FeMesh{mesh_scale, std::nullopt});
}

std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const std::string& case_file,
                                          double mesh_scale) {
  return fe_probes(cache, case_file, FeMesh{mesh_scale, std::nullopt});
}

std::shared_ptr<const FeProbes> analytic_probes(ComputeCache& cache, const std::string& case_file,
                                                const std::string& model, double tolerance,
                                                int n_max) {
  const std::string key = "analytic:" + case_file + ":" + model + ":" + std::to_string(tolerance) +
                          ":" + std::to_string(n_max);
  return cache.get<FeProbes>(key, [&] {
    AnalyticOptions o;
    o.model = model;
    o.tolerance = tolerance;
    o.n_max = n_max;
    const auto run = run_case_analytic(*cached_case(cache, case_file), o);
    FeProbes out;
    out.probes = run->probes;
    out.seconds = run->total_s;
    return out;
  });
}

const std::map<std::string, Evaluator>& evaluator_registry() {
  static const std::map<std::string, Evaluator> registry = [] {
    std::map<std::string, Evaluator> r;
    register_thesis_ch3(r);
    register_thesis_ch4(r);
    register_thesis_ch5(r);
    register_thesis_ch6(r);
    register_harwin(r);
    register_voicecoil(r);
    register_dmp(r);
    register_demagnetization(r);
    return r;
  }();
  return registry;
}

} // namespace magfem
