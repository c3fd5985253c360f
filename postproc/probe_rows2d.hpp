#pragma once
// A 2D probe's sample points and its CSV table from field values at those points, shared by
// the FE sampler (probes2d.hpp) and the analytic axisymmetric models, so both write the same
// columns (see probes2d.hpp for the contract).
#include <vector>

#include <Eigen/Core>

#include "postproc/probe_spec.hpp"
#include "postproc/probe_table.hpp"

namespace magfem {

// Sample points (metres, x = r in axisymmetric cases) in CSV row order.
std::vector<Eigen::Vector2d> probe_points_2d(const ProbeSpec& probe);

// B[i] at points[i] = probe_points_2d(probe)[i]; `axi` picks the r-z column names.
ProbeTable tabulate_probe_2d(const ProbeSpec& probe, const std::vector<Eigen::Vector2d>& points,
                             const std::vector<Eigen::Vector2d>& B, double length_unit, bool axi);

} // namespace magfem
