#pragma once
// The summary.json blocks every solve writes, planar, axisymmetric and 3D alike, written in
// one place so that the three keep the one schema of docs/summary.schema.json (a test checks
// the examples' summaries against it). What only one dimension has (a 3D memory guard, 3D
// sections, axisymmetric coils) stays with its pipeline.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "pipeline/timings.hpp"
#include "solver/newton.hpp"

namespace magfem {

struct RunHeader {
  std::string case_file;
  nlohmann::ordered_json dimension; // 2, "axi" or 3
  int order = 0;
  std::size_t elements = 0, nodes = 0;
  std::size_t unknowns = 0;      // every DOF, those fixed by boundary conditions included
  std::size_t free_unknowns = 0; // the size of the system solved (the console's "unknowns")
};

// Provenance (version, commit), case, dimension, order, elements, nodes, unknowns,
// free_unknowns.
void add_run_header(nlohmann::ordered_json& j, const RunHeader& header);

// What the energy and forces of this summary are the whole of: "metre of length" (planar
// without stack), "stack", "body of revolution" (axisymmetric), "device" (3D).
void add_energy(nlohmann::ordered_json& j, double energy_J, const std::string& per);

struct ErrorEstimateRecord {
  double energy_error_pct = 0;      // 100 eta^2 / (2 W): the estimated relative error of W
  double energy_norm_error_pct = 0; // the relative energy-norm error
  std::string indicator;            // the estimator's name
  double error_norm2_J = 0;         // eta^2, in the units of energy_J (J per energy_per)
  std::size_t degraded_patches = 0; // recovery fits that fell back a degree (PatchRecovery*)
};

// error_estimate {energy_error_pct, energy_norm_error_pct, indicator, error_norm2_J,
// degraded_patches, scope, seconds}: the same meaning in every dimension
// (postproc/error_estimate2d, 3d).
void add_error_estimate(nlohmann::ordered_json& j, const ErrorEstimateRecord& e, double seconds);

// converged, iterations, residual_history, the solver block (solver_summary.hpp), timings_s
// and peak_memory_MB.
void add_solve_record(nlohmann::ordered_json& j, const NewtonReport& report, const Timings& timings,
                      int threads, int ranks);

} // namespace magfem
