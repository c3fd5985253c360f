// Torques about a point other than the origin, through the whole pipeline (case file ->
// forces): every force entry of one solve is repeated with `torque_point` at the origin, at
// an off-axis point p, and left out (the default: the entry's `center`). Moving the point
// from 0 to p changes the torque by exactly -p x F,
//   T_p = sum (x - p) x f = T_0 - p x F,
// for any quadrature and any field, so the three torques of an entry must satisfy this to
// round-off (1e-12 of |T_0| + |p| |F|), on a coarse mesh. The cases have a net force on what
// is measured (else p x F = 0 and the point could be ignored unseen): an off-centre magnet
// between two conductors (2D) and a magnet with a coaxial coil (3D, axial force, p off the
// axis). A torque point ignored, read as the centre, added instead of subtracted, or
// F x r instead of r x F fails the identity by |p x F|, which is asserted to be far above
// round-off. The physics of the torques themselves (against exact values about an off-origin
// point) is in tests/postproc/test_force2d.cpp and test_force3d.cpp.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <Eigen/Geometry>

#include "pipeline/run3d.hpp"
#include "tests/case_helpers.hpp"

using namespace magfem;

namespace {

template <class Run> const ForceResult& force(const Run& run, const std::string& name) {
  for (const auto& f : run.forces)
    if (f.name == name)
      return f;
  throw std::runtime_error("no force " + name);
}

// Checks T_p = T_0 - p x F for the entries `stem`0 (about the origin) and `stem`p (about p),
// and that both have the same force; returns |p x F| / (|T_0| + |p| |F|), how much the
// point matters.
template <class Run>
double expect_moved_torque(const Run& run, const std::string& stem, const Eigen::Vector3d& p) {
  const ForceResult& at0 = force(run, stem + "0");
  const ForceResult& atp = force(run, stem + "p");
  const double scale = at0.torque.norm() + p.norm() * at0.force.norm();
  const Eigen::Vector3d expected = at0.torque - p.cross(at0.force);
  std::printf("%s: F (%.4g, %.4g, %.4g), T_0 (%.4g, %.4g, %.4g), T_p (%.4g, %.4g, %.4g), "
              "expected (%.4g, %.4g, %.4g)\n",
              stem.c_str(), at0.force.x(), at0.force.y(), at0.force.z(), at0.torque.x(),
              at0.torque.y(), at0.torque.z(), atp.torque.x(), atp.torque.y(), atp.torque.z(),
              expected.x(), expected.y(), expected.z());
  EXPECT_EQ(atp.force, at0.force) << stem;
  EXPECT_LT((atp.torque - expected).norm(), 1e-12 * scale) << stem;
  return p.cross(at0.force).norm() / scale;
}

// 2D (mm): magnet of radius 10 at (5, 2), magnetized at 60 deg, between conductors of radius
// 8 at (0, +-30) carrying +-20 kA (tests/postproc/test_force2d.cpp's case, coarser).
const char* case_2d = R"(title: torque point 2D
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.0, mu_r: 1.0}
regions:
  - {name: magnet, shape: disk, center: [5, 2], radius: 10, material: pm,
     magnetization: {type: parallel, angle: 60}, mesh_size: 2}
  - {name: upper, shape: disk, center: [0, 30], radius: 8, turns: 1, current: 20000,
     mesh_size: 2}
  - {name: lower, shape: disk, center: [0, -30], radius: 8, turns: 1, current: -20000,
     mesh_size: 2}
boundary: {type: open, radius: 50}
mesh: {size: 4}
solver: {order: 2}
forces:
  - {name: circle0, type: circle, center: [5, 2], radius: 14, torque_point: [0, 0]}
  - {name: circlep, type: circle, center: [5, 2], radius: 14, torque_point: [13, 7]}
  - {name: circlec, type: circle, center: [5, 2], radius: 14}
  - {name: band0, type: band, center: [5, 2], r_inner: 11, r_outer: 17, torque_point: [0, 0]}
  - {name: bandp, type: band, center: [5, 2], r_inner: 11, r_outer: 17, torque_point: [13, 7]}
  - {name: lorentz0, type: lorentz, regions: [upper], torque_point: [0, 0]}
  - {name: lorentzp, type: lorentz, regions: [upper], torque_point: [13, 7]}
)";

// 3D (mm): examples/3d/coil_and_magnet.yaml at a coarse mesh; the force is along the axis,
// p = (7, -3, 2) mm is off it, so p x F has x and y components.
const char* case_3d = R"(title: torque point 3D
dimension: 3
unit: mm
materials:
  pm: {kind: magnet, B_r: 1.2, mu_r: 1.0}
regions:
  - {name: magnet, shape: cylinder, r_outer: 5, height: 10, material: pm,
     magnetization: {type: axial}, placement: {translate: [0, 0, -5]}, mesh_size: 3}
coils:
  - {name: coil, shape: solenoid, r_inner: 4, r_outer: 8, length: 10, center: [0, 0, 20],
     axis: [0, 0, 1], turns: 500, current: 2, fill_factor: 0.6}
boundary: {type: open, radius: 60}
mesh: {size: 15, chord_tolerance: 0.3, probe_size: 4}
solver: {order: 1}
forces:
  - {name: sphere0, type: sphere, radius: 11, torque_point: [0, 0, 0]}
  - {name: spherep, type: sphere, radius: 11, torque_point: [7, -3, 2]}
  - {name: box0, type: box, size: [22, 22, 22], torque_point: [0, 0, 0]}
  - {name: boxp, type: box, size: [22, 22, 22], torque_point: [7, -3, 2]}
  - {name: lorentz0, type: lorentz, coils: [coil], torque_point: [0, 0, 0]}
  - {name: lorentzp, type: lorentz, coils: [coil], torque_point: [7, -3, 2]}
)";

constexpr double mm = 1e-3;

} // namespace

TEST(TorquePoint, Forces2DAboutAnyPointDifferByPCrossF) {
  const auto run = run_case_2d(read_case(test::write_temp_case("torque_point_2d.yaml", case_2d)));
  const Eigen::Vector3d p(13 * mm, 7 * mm, 0);
  for (const char* stem : {"circle", "band", "lorentz"})
    EXPECT_GT(expect_moved_torque(*run, stem, p), 0.1) << stem; // the point matters here
  // Without torque_point the torque is about the centre c = (5, 2) mm.
  const ForceResult& at0 = force(*run, "circle0");
  const Eigen::Vector3d c(5 * mm, 2 * mm, 0);
  const double scale = at0.torque.norm() + c.norm() * at0.force.norm();
  EXPECT_LT((force(*run, "circlec").torque - (at0.torque - c.cross(at0.force))).norm(),
            1e-12 * scale);
}

TEST(TorquePoint, Forces3DAboutAnyPointDifferByPCrossF) {
  const auto run =
      run_case_3d(read_case(test::write_temp_case("torque_point_3d.yaml", case_3d)), {});
  const Eigen::Vector3d p(7 * mm, -3 * mm, 2 * mm);
  for (const char* stem : {"sphere", "box", "lorentz"})
    EXPECT_GT(expect_moved_torque(*run, stem, p), 0.1) << stem;
}
