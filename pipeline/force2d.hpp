#pragma once
// Forces of a 2D run (case `forces:` entries): stress tensor on circles, Arkkio bands,
// Lorentz force on current regions. Per metre of length, or times the stack length.
#include <vector>

#include "pipeline/force_results.hpp"

namespace magfem {

struct Run2D;
std::vector<ForceResult> compute_forces_2d(const Run2D& run);

} // namespace magfem
