#pragma once
// A sweep position solved adaptively (the case's `adapt:` section, pipeline/solve_case.hpp):
// what it refines for, and what its rows, checkpoint, summary and console say about it.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "casefile/case_spec.hpp"
#include "pipeline/adapt_loop.hpp"

namespace magfem {

struct PositionAdapt {
  int passes = 0; // 0: the position was solved on one mesh
  bool converged = false;
  double error_pct = 0; // the refined quantity's estimated relative error (NaN: unknown)
};

// A sweep refines each position for what it reports: the force entry `force_name` (the sweep's
// own, which the sweep adds to the case) in `component` (torque, force, Fz...); the case's
// own quantities may name forces or probes a sweep drops. No-op without an adapt: section.
void aim_adapt_at(CaseSpec& spec, const std::string& force_name, const std::string& component);

PositionAdapt position_adapt(const std::optional<AdaptHistory>& history);

// The refined quantity's estimated error in its unit, from its relative estimate and its
// magnitude; NaN when the position did not adapt or has no estimate.
double position_adapt_error(const PositionAdapt& a, double magnitude);

// The checkpoint's keys (absent in checkpoints written before adaptive sweeps: one mesh).
void add_position_adapt(nlohmann::json& row, const PositionAdapt& a);
PositionAdapt position_adapt_from_json(const nlohmann::json& row);

// summary.json positions[].adapt: {passes, converged, estimated_error_pct}.
nlohmann::ordered_json position_adapt_summary(const PositionAdapt& a);

// The warning for a position that stopped at a limit ("" when it converged or did not adapt).
std::string position_adapt_warning(const std::string& key, double position, const PositionAdapt& a);

} // namespace magfem
