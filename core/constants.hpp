#pragma once
// Physical and mathematical constants, SI units.
#include <numbers>

namespace magfem {

inline constexpr double pi = std::numbers::pi;
// Vacuum permeability in H/m. The classical 4*pi*1e-7 is used (the 2019 SI value differs by
// 5.5e-10 relative, far below any discretization error we report).
inline constexpr double mu0 = 4.0e-7 * pi;
inline constexpr double nu0 = 1.0 / mu0;
inline constexpr double deg_to_rad = pi / 180.0;
inline constexpr double rad_to_deg = 180.0 / pi;

} // namespace magfem
