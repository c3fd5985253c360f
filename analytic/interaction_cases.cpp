#include "analytic/interaction_cases.hpp"

#include <cmath>
#include <cstdio>

#include "core/constants.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

Vec3 unit(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

} // namespace

std::vector<AnalyticMagnet> segment_array(double r_inner, double r_outer, int p_theta, int p_phi,
                                          double B_r, double theta_max,
                                          const Placement& placement) {
  std::vector<AnalyticMagnet> out;
  const double dt = theta_max / p_theta, dp = 2 * pi / p_phi;
  for (int i = 0; i < p_theta; ++i)
    for (int j = 0; j < p_phi; ++j) {
      AnalyticMagnet m;
      m.shape = SphericalSegment{r_inner, r_outer, i * dt, (i + 1) * dt, j * dp, (j + 1) * dp};
      m.placement = placement;
      m.magnetization.pattern = Magnetization::Pattern::parallel;
      m.magnetization.direction = placement.rotation * unit((i + 0.5) * dt, (j + 0.5) * dp);
      m.magnetization.sign = (i + j) % 2 ? -1.0 : 1.0;
      m.B_r = B_r;
      char name[32];
      std::snprintf(name, sizeof name, "s%d_%d", i, j);
      m.name = name;
      out.push_back(m);
    }
  return out;
}

std::vector<AnalyticMagnet> cylinder_array(double rc, double h, double rb, double pitch, double B_r,
                                           double sign, const Placement& placement) {
  std::vector<AnalyticMagnet> out;
  auto place_one = [&](double theta, double phi) {
    const Vec3 axis = unit(theta, phi);
    const Eigen::Matrix3d r =
        Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix();
    AnalyticMagnet m;
    m.shape = Cylinder{0, rc, h};
    m.placement = {placement.rotation * r, placement.to_global(rb * axis)};
    m.magnetization.pattern = Magnetization::Pattern::parallel;
    m.magnetization.direction = m.placement.rotation * Vec3::UnitZ();
    m.magnetization.sign = sign;
    m.B_r = B_r;
    char name[32];
    std::snprintf(name, sizeof name, "c%zu", out.size() + 1);
    m.name = name;
    out.push_back(m);
  };
  const double dtheta = pitch / rb;
  place_one(0, 0);
  for (double theta = dtheta; theta <= 0.5 * pi - 0.5 * dtheta + 1e-12; theta += dtheta) {
    const int n = static_cast<int>(std::floor(2 * pi * rb * std::sin(theta) / pitch));
    for (int k = 0; k < n; ++k)
      place_one(theta, 2 * pi * k / n);
  }
  return out;
}

InteractionCase segment_coupling_case() {
  const Placement tilt = Placement{}.rotated(Vec3::UnitY(), 20 * deg_to_rad, Vec3::Zero());
  return {"segment arrays (32 in 16, 2 mm gap)", segment_array(0.040, 0.055, 4, 8, 1.3, pi, tilt),
          segment_array(0.057, 0.065, 2, 8, 1.3, 0.5 * pi)};
}

InteractionCase prototype_case(double height, double angle_deg) {
  AnalyticMagnet inner;
  inner.shape = SphericalSegment{0, 0.0254, 0, 0.5 * pi, 0, 2 * pi};
  inner.magnetization.pattern = Magnetization::Pattern::parallel;
  inner.magnetization.direction = Vec3::UnitZ();
  inner.B_r = 1.345;
  inner.name = "inner";
  const Placement turn = Placement{}.rotated(Vec3::UnitY(), angle_deg * deg_to_rad, Vec3::Zero());
  return {"compensator prototype (180 cylinders, hemisphere)",
          cylinder_array(0.002, height, 0.0279, 0.00514, 1.305, -1.0, turn),
          {inner}};
}

InteractionCase cylinder_pair_case() {
  auto cylinder = [](const Vec3& base) {
    AnalyticMagnet m;
    m.shape = Cylinder{0, 0.005, 0.010};
    m.placement.translation = base;
    m.magnetization.pattern = Magnetization::Pattern::parallel;
    m.magnetization.direction = Vec3::UnitZ();
    m.B_r = 1.3;
    return m;
  };
  return {"two cylinders r 5 h 10 mm, 1 mm gap, 3 mm offset",
          {cylinder(Vec3(0.003, 0, 0.011))},
          {cylinder(Vec3::Zero())}};
}

} // namespace magfem
