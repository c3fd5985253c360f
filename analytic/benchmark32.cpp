#include "analytic/benchmark32.hpp"

#include <cmath>

#include "core/constants.hpp"

namespace magfem {

std::string to_string(Benchmark32Magnetization kind) {
  switch (kind) {
  case Benchmark32Magnetization::parallel_centred:
    return "parallel_centred";
  case Benchmark32Magnetization::parallel_edge:
    return "parallel_edge";
  case Benchmark32Magnetization::radial:
    return "radial";
  }
  return "unknown";
}

std::vector<AnalyticMagnet> make_benchmark32(Benchmark32Magnetization kind, double B_r) {
  const double step = pi / 4; // 45 deg pole pitch in both angles
  std::vector<AnalyticMagnet> magnets;
  for (int pt = 1; pt <= Benchmark32::n_theta; ++pt) {
    for (int pp = 1; pp <= Benchmark32::n_phi; ++pp) {
      AnalyticMagnet m;
      m.shape = SphericalSegment{Benchmark32::r_inner, Benchmark32::r_outer,
                                 step * (pt - 1),      step * pt,
                                 step * (pp - 1),      step * pp};
      m.B_r = B_r;
      // Appended piece by piece: GCC 12 reports a false -Wrestrict on "literal" + std::string.
      m.name = std::string("m").append(std::to_string(pt)).append("_").append(std::to_string(pp));
      m.magnetization.sign = ((pt + pp) % 2 == 0) ? 1.0 : -1.0;
      if (kind == Benchmark32Magnetization::radial) {
        m.magnetization.pattern = Magnetization::Pattern::radial;
        m.magnetization.center = Eigen::Vector3d::Zero();
      } else {
        const double lt = step * (pt - 0.5);
        const double lp =
            step * (kind == Benchmark32Magnetization::parallel_centred ? pp - 0.5 : pp - 1.0);
        m.magnetization.pattern = Magnetization::Pattern::parallel;
        m.magnetization.direction =
            Eigen::Vector3d(std::sin(lt) * std::cos(lp), std::sin(lt) * std::sin(lp), std::cos(lt));
      }
      magnets.push_back(m);
    }
  }
  return magnets;
}

} // namespace magfem
