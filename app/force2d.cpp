#include "app/force2d.hpp"

#include <stdexcept>

#include "app/run2d.hpp"
#include "core/input_error.hpp"
#include "postproc/lorentz2d.hpp"
#include "postproc/maxwell_stress2d.hpp"
#include "postproc/point_locator2d.hpp"

namespace magfem {
namespace {

ForceResult from(const ForceTorque& ft, double length) {
  ForceResult r;
  r.force = length * ft.force;
  r.torque = length * ft.torque;
  return r;
}

} // namespace

std::vector<ForceResult> compute_forces_2d(const Run2D& run) {
  std::vector<ForceResult> out;
  if (run.spec.forces.empty())
    return out;
  const PointLocator2D locator(run.mesh);
  const FieldSampler2D sampler(*run.field, locator);
  const double length = run.spec.stack_length > 0 ? run.spec.stack_length : 1.0;
  for (const auto& f : run.spec.forces) {
    const Eigen::Vector2d c = f.center.head<2>(), p = f.torque_point.head<2>();
    ForceResult r;
    try {
      switch (f.kind) {
      case ForceSpec::Kind::circle:
        r = from(maxwell_stress_circle_2d(sampler, c, f.radius, p), length);
        r.method = "stress_circle";
        if (f.check_radius > 0) {
          const ForceResult second =
              from(maxwell_stress_circle_2d(sampler, c, f.check_radius, p), length);
          r.checked = true;
          r.check_force = second.force;
          r.check_torque = second.torque;
          r.check_relative_difference = relative_difference(r, second, f.radius);
        }
        break;
      case ForceSpec::Kind::band:
        r = from(maxwell_stress_band_2d(sampler, c, f.r_inner, f.r_outer, p), length);
        r.method = "arkkio_band";
        break;
      case ForceSpec::Kind::lorentz: {
        std::vector<int> parts;
        for (const auto& name : f.regions)
          for (std::size_t i = 0; i < run.spec.regions.size(); ++i)
            if (run.spec.regions[i].name == name)
              parts.push_back(static_cast<int>(i));
        r = from(lorentz_force_2d(*run.field, parts, p), length);
        r.method = "lorentz";
        break;
      }
      case ForceSpec::Kind::sphere:
      case ForceSpec::Kind::box:
        continue; // 3D only; the reader does not allow it in 2D
      }
    } catch (const std::invalid_argument& e) {
      // The surface crosses matter or leaves the domain: the case file is at fault.
      throw InputError(run.spec.file, f.line, "forces." + f.name, e.what());
    }
    r.name = f.name;
    out.push_back(r);
  }
  return out;
}

} // namespace magfem
