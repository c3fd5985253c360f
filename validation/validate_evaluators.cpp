#include "validation/validate_evaluators.hpp"

#include <chrono>

#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/run3d.hpp"
#include "pipeline/run_analytic.hpp"

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
  return {{"mesh_scale", mesh_scale},
          {"elements", elements},
          {"unknowns", unknowns},
          {"iterations", iterations},
          {"seconds", seconds}};
}

std::shared_ptr<const CaseSpec> cached_case(ComputeCache& cache, const std::string& case_file) {
  return cache.get<CaseSpec>("case:" + case_file, [&] { return read_case(case_file); });
}

std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const CaseSpec& spec,
                                          const std::string& key, double mesh_scale) {
  return cache.get<FeProbes>("fe:" + key + ":" + std::to_string(mesh_scale), [&] {
    const auto t0 = Clock::now();
    RunOverrides ov;
    ov.mesh_scale = mesh_scale;
    FeProbes out;
    out.mesh_scale = mesh_scale;
    CaseSpec copy = spec;
    copy.write_vtu = false;
    if (spec.dimension == 3) {
      const auto run = run_case_3d(std::move(copy), ov);
      out.probes = run->probes;
      out.demagnetization = run->demagnetization.magnets;
      out.elements = static_cast<long>(run->mesh.n_tets());
      out.unknowns = static_cast<long>(run->dofs->n_dofs());
      out.iterations = run->report.iterations;
    } else {
      const auto run = run_case_2d(std::move(copy), ov);
      out.probes = run->probes;
      out.demagnetization = run->demagnetization.magnets;
      out.elements = static_cast<long>(run->mesh.n_triangles());
      out.unknowns = static_cast<long>(run->dofs->n_dofs());
      out.iterations = run->report.iterations;
    }
    out.seconds = since(t0);
    return out;
  });
}

std::shared_ptr<const FeProbes> fe_probes(ComputeCache& cache, const std::string& case_file,
                                          double mesh_scale) {
  return fe_probes(cache, *cached_case(cache, case_file), case_file, mesh_scale);
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
