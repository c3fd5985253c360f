#pragma once
// The thesis's 32-magnet spherical benchmark (thesis ch. 3, Table 3.1; paper_targets.md A):
// full shell 40..55 mm cut into 4 x 8 segments of 45 x 45 deg, B_r 1.3 T, alternating signs.
#include <string>
#include <vector>

#include "analytic/analytic_magnet.hpp"

namespace magfem {

enum class Benchmark32Magnetization {
  parallel_centred, // direction at the segment centre: lambda_phi = 45 (p_phi - 1/2) deg
  parallel_edge,    // literal eq. 3.113: lambda_phi = 45 (p_phi - 1) deg
  radial            // eq. 3.116: +- M0 e_rho about the origin
};

std::string to_string(Benchmark32Magnetization kind);

// Geometry constants of the benchmark (SI).
struct Benchmark32 {
  static constexpr double r_inner = 0.040;
  static constexpr double r_outer = 0.055;
  static constexpr int n_theta = 4;
  static constexpr int n_phi = 8;
  static constexpr double r_observation = 0.056;
};

// Magnet (p_theta, p_phi), counted from 1, spans theta [45(p_theta-1), 45 p_theta] deg and
// phi [45(p_phi-1), 45 p_phi] deg, sign (-1)^(p_theta+p_phi); parallel direction angles
// lambda_theta = 45 (p_theta - 1/2) deg and lambda_phi as above. Identity placement.
// Order: p_theta outer, p_phi inner; names "m<p_theta>_<p_phi>".
std::vector<AnalyticMagnet> make_benchmark32(Benchmark32Magnetization kind, double B_r = 1.3);

} // namespace magfem
