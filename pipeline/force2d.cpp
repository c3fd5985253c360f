#include "pipeline/force2d.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "casefile/symmetry_check2d.hpp"
#include "core/input_error.hpp"
#include "pipeline/run2d.hpp"
#include "pipeline/symmetry2d.hpp"
#include "postproc/lorentz2d.hpp"
#include "postproc/maxwell_stress2d.hpp"
#include "postproc/maxwell_stress_axi.hpp"
#include "postproc/point_locator2d.hpp"

namespace magfem {
namespace {

// Axisymmetric: the circle about a centre on the axis, revolved, is a sphere; the 3D sphere
// quadrature is used as is, with the r-z field revolved to the point (the 3D z axis is the
// axis of revolution). The integrand varies with phi only like cos and sin, which a few
// trapezoid points integrate exactly.
ForceTorque stress_sphere_axi(const FieldSampler2D& sampler, const Eigen::Vector2d& center,
                              double radius) {
  constexpr int n_theta = 1024, n_phi = 4;
  const FieldFunction revolved = [&sampler](const Eigen::Vector3d& x) {
    const double r = std::hypot(x.x(), x.y());
    const Eigen::Vector2d b = sampler.B({r, x.z()});
    const Eigen::Vector2d e_r =
        r > 0 ? Eigen::Vector2d(x.x() / r, x.y() / r) : Eigen::Vector2d(1, 0);
    return Eigen::Vector3d(b.x() * e_r.x(), b.x() * e_r.y(), b.y());
  };
  const Eigen::Vector3d c(0, 0, center.y());
  ForceTorque ft = maxwell_stress_on_sphere(revolved, c, radius, c, n_theta, n_phi);
  ft.force.head<2>().setZero(); // zero by symmetry; drop the quadrature's round-off
  ft.torque.setZero();
  return ft;
}

ForceTorque stress_circle(const FieldSampler2D& sampler, bool axi, const Eigen::Vector2d& c,
                          double radius, const Eigen::Vector2d& p) {
  return axi ? stress_sphere_axi(sampler, c, radius)
             : maxwell_stress_circle_2d(sampler, c, radius, p);
}

// F_z on a region by the stress tensor on the revolved box `margin` outside the bounding box
// of its mesh nodes (a box hugs cylinders, rings and coils, which a sphere about the axis
// often cannot separate from their neighbours).
ForceTorque stress_contour_axi(const FieldSampler2D& sampler, const Mesh2D& mesh, int part,
                               double margin, const std::vector<std::vector<int>>& mirrors) {
  const auto box_of = [&mesh](int q, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
    lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
    hi = -lo;
    for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
      if (mesh.triangle_part[t] == q)
        for (const int v : mesh.triangles[t]) {
          lo = lo.cwiseMin(mesh.nodes[v]);
          hi = hi.cwiseMax(mesh.nodes[v]);
        }
    return lo.x() <= hi.x();
  };
  Eigen::Vector2d lo, hi;
  const bool meshed = box_of(part, lo, hi);
  for (std::size_t k = 0; k < mesh.symmetry.size(); ++k) {
    const int axis = mesh.symmetry[k].axis, image = mirrors[k][std::size_t(part)];
    if (image == part) // cut by the plane: it reaches as far beyond it as on the model's side
      lo[axis] = -hi[axis];
    else if (!meshed && image >= 0 && box_of(image, lo, hi)) { // beyond: its image's, mirrored
      const double a = lo[axis];
      lo[axis] = -hi[axis];
      hi[axis] = -a;
    }
  }
  const double r_min = lo.x() - margin > 0 ? lo.x() - margin : 0.0;
  const auto contour = box_contour(r_min, hi.x() + margin, lo.y() - margin, hi.y() + margin);
  ForceTorque ft;
  ft.force.z() =
      maxwell_stress_axial_force([&](const Eigen::Vector2d& x) { return sampler.B(x); }, contour);
  return ft;
}

int part_index(const Run2D& run, const std::string& name) {
  for (std::size_t i = 0; i < run.spec.regions.size(); ++i)
    if (run.spec.regions[i].name == name)
      return static_cast<int>(i);
  return -1; // the reader checked the names
}

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
  const bool axi = run.spec.axisymmetric();
  for (const auto& f : run.spec.forces) {
    const Eigen::Vector2d c = f.center.head<2>(), p = f.torque_point.head<2>();
    ForceResult r;
    try {
      switch (f.kind) {
      case ForceSpec::Kind::circle:
        r = from(stress_circle(sampler, axi, c, f.radius, p), length);
        r.method = axi ? "stress_sphere" : "stress_circle";
        if (f.check_radius > 0) {
          const ForceResult second =
              from(stress_circle(sampler, axi, c, f.check_radius, p), length);
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
        r = from(lorentz_force_whole_2d(*run.field, parts, p, run.spec), length);
        r.method = "lorentz";
        break;
      }
      case ForceSpec::Kind::contour:
        r = from(stress_contour_axi(sampler, run.mesh, part_index(run, f.regions.front()), f.margin,
                                    mirror_parts_2d(run.spec)),
                 length);
        r.method = "stress_contour";
        break;
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
