#pragma once
// The error measure of the voice-coil paper's Table 1 (002_5cbab31495bf2c6b.txt, sec. III.A):
// %Error = 100 int_0^Y |B_z,ML(y) - B_z,ESL(y)| dy / int_0^Y |B_z,ML(y)| dy along a radial line
// near the end face. The paper does not print Y; y_max <= 0 here means the whole line
// (0 .. infinity), the limit the measure tends to.
#include <functional>
#include <vector>

namespace magfem {

struct RadialL1 {
  double difference = 0; // int |reference - model| dy
  double reference = 0;  // int |reference| dy
  double percent() const { return 100.0 * difference / reference; }
};

// Composite 8-point Gauss on panels graded geometrically (ratio 1/4) towards every breakpoint
// (where a field has a kink or a near-jump, e.g. the radii of a winding near its end face) down
// to `finest`; beyond 4 times the largest breakpoint (y_max <= 0) the tail is mapped to
// (0, 1] by y = Y0 / t, which the 1/y^2 (2D) and 1/y^3 (3D) decay makes smooth.
RadialL1 radial_l1_difference(const std::function<double(double)>& reference,
                              const std::function<double(double)>& model,
                              std::vector<double> breakpoints, double y_max, double finest);

} // namespace magfem
