#pragma once
// magfem._core.Analytic: a case answered by the analytic models (pipeline/run_analytic.hpp), with
// what Python reads from it. The models are not kept after the run, so there is no field at
// arbitrary points here: probes are the points (python/magfem/solution.py wraps it into
// magfem.AnalyticSolution).
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "pipeline/run_analytic.hpp"

namespace magfem::python {

class Analytic {
public:
  explicit Analytic(std::unique_ptr<AnalyticRun> run) : run_(std::move(run)) {}

  std::string forces_json() const; // as summary.json's "forces"
  pybind11::dict probes() const;   // name -> {column: numpy array}
  std::vector<std::string> write(const std::string& dir) const;
  std::string summary_json() const; // the writer's own summary_json_analytic

private:
  std::unique_ptr<AnalyticRun> run_;
  mutable std::mutex output_mutex_; // write() one at a time, as Solution's
};

void bind_analytic(pybind11::module_& m);

} // namespace magfem::python
