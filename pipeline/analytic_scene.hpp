#pragma once
// What of a 3D case the analytic models can represent: permanent magnets (spherical segments,
// cylinders, boxes) of mu_r = 1 in air, and infinitely permeable spheres, which come from
// (a) a full spherical shell or ball of a linear material with mu_r >= 1000 centred on the
// origin, or (b) a Dirichlet outer boundary (phi = 0 on the sphere is exactly the condition
// on an infinitely permeable boundary). Air regions are mesh aids and are ignored. Anything
// else (nonlinear iron, moderate mu_r, Neumann boundaries) is rejected with an InputError
// naming the region and its line.
#include <string>
#include <vector>

#include "casefile/case_spec.hpp"
#include "analytic/analytic_magnet.hpp"

namespace magfem {

struct AnalyticScene {
  std::vector<AnalyticMagnet> magnets;
  std::vector<PermeableSphere> spheres;
  std::vector<std::string> notes; // approximations made (recoil mu_r ignored, mu_r -> inf)
};

AnalyticScene analytic_scene(const CaseSpec& spec);

// Air regions: linear with mu_r exactly 1 (mesh aids the analytic models ignore).
bool is_air(const Material& m);
// A full ball or shell centred on the origin: what spherical imaging can represent.
bool full_sphere_at_origin(const Part3D& part);

} // namespace magfem
