#include "pipeline/run_summary.hpp"

#include "pipeline/build_info.hpp"
#include "pipeline/resource_usage.hpp"
#include "pipeline/solver_summary.hpp"

namespace magfem {

void add_run_header(nlohmann::ordered_json& j, const RunHeader& header) {
  add_provenance(j);
  j["case"] = header.case_file;
  j["dimension"] = header.dimension;
  j["order"] = header.order;
  j["elements"] = header.elements;
  j["nodes"] = header.nodes;
  j["unknowns"] = header.unknowns;
  j["free_unknowns"] = header.free_unknowns;
}

void add_energy(nlohmann::ordered_json& j, double energy_J, const std::string& per) {
  j["energy_J"] = energy_J;
  j["energy_per"] = per;
}

void add_error_estimate(nlohmann::ordered_json& j, const ErrorEstimateRecord& e, double seconds) {
  j["error_estimate"] = {
      {"energy_error_pct", e.energy_error_pct},
      {"energy_norm_error_pct", e.energy_norm_error_pct},
      {"indicator", e.indicator},
      {"error_norm2_J", e.error_norm2_J},
      {"degraded_patches", e.degraded_patches},
      {"scope", "whole domain, the open-boundary shell (the mapped exterior) included"},
      {"seconds", seconds}};
}

void add_solve_record(nlohmann::ordered_json& j, const NewtonReport& report, const Timings& timings,
                      int threads, int ranks) {
  j["converged"] = report.converged;
  j["iterations"] = report.iterations;
  j["residual_history"] = report.residual_history;
  add_solver_summary(j, report, threads, ranks);
  j["timings_s"] = {{"mesh", timings.mesh},
                    {"assemble", timings.assemble},
                    {"solve", timings.solve},
                    {"linear_setup", report.linear_setup_s},
                    {"linear_solve", report.linear_solve_s},
                    {"postprocess", timings.postprocess},
                    {"error_estimate", timings.error_estimate},
                    {"total", timings.total}};
  j["peak_memory_MB"] = peak_memory_mb();
}

} // namespace magfem
