#include "materials/magnet_knee.hpp"

#include "core/constants.hpp"

namespace magfem {

double knee_flux_density(double B_r, double mu_r, double HcJ_Apm) {
  // The recoil line B = B_r + mu0 mu_r H at H = -H_cJ.
  return B_r - mu0 * mu_r * HcJ_Apm;
}

} // namespace magfem
