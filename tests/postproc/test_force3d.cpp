// 3D force and torque (postproc/maxwell_stress3d.hpp) against exact values.
//
// The case: two uniformly magnetized spheres (mu_r 1) at a distance. The field outside each
// is exactly that of a point dipole m = (4/3) pi a^3 B_r / mu0 m_hat at its centre, and a
// uniformly magnetized sphere in a source-free external field feels exactly the force and
// torque of that dipole (mean-value property of harmonic fields), so
//   F on 2 = 3 mu0 / (4 pi r^4) [(m1.u) m2 + (m2.u) m1 + (m1.m2) u - 5 (m1.u)(m2.u) u],
//   u = (c2 - c1) / r,  torque on 2 about its centre = m2 x B1(c2),
// and the forces and torques on 1 follow by action and reaction. The spheres are curved
// (isoparametric P2), so their moments are right on coarse meshes too.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include <Eigen/Geometry>

#include "core/constants.hpp"
#include "mesh/mesher3d.hpp"
#include "postproc/maxwell_stress3d.hpp"
#include "solver/assembler3d.hpp"
#include "solver/newton.hpp"

namespace magfem {
namespace {

using V3 = Eigen::Vector3d;
constexpr double mm = 1e-3;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct PairCase {
  std::array<V3, 2> center = {V3(-11 * mm, 0, -2 * mm), V3(11 * mm, 0, 2 * mm)};
  std::array<double, 2> radius = {8 * mm, 8 * mm};
  double B_r = 1.0;
  double stress_radius = 12.5 * mm; // refined band about each magnet (gap: 8 .. 14.4 mm)
  double domain = 28 * mm;          // open boundary (mapped shell) beyond
  double magnet_size = 1.5 * mm;    // element sizes, times size_scale
  double air_size = 5 * mm;
  double probe_size = 2 * mm;
  double chord = 0.05 * mm;
  double size_scale = 1.0;
  int order = 2;
};

// Owns everything the field refers to; one mesh, solved for any pair of directions.
struct PairSolution {
  Material air = Material::make_linear("air", 1.0, "test");
  Material magnet = Material::make_magnet("magnet", 1.0, 1.0, "test");
  Mesh3D mesh;
  Problem3D problem;
  std::unique_ptr<DofMap3D> dofs;
  std::unique_ptr<Field3D> field;
  std::unique_ptr<PointLocator3D> locator;
  int n_unknowns = 0;
  double solve_s = 0;
};

Geometry3D pair_geometry(const PairCase& c) {
  Geometry3D g;
  g.outer = {OuterKind3D::open, c.domain, 1.5};
  g.options.default_size = c.air_size;
  g.options.chord_tolerance = c.chord;
  g.options.size_scale = c.size_scale;
  g.options.probe_size = c.probe_size;
  for (int k = 0; k < 2; ++k) {
    Part3D p{k == 0 ? "a" : "b", SphericalSegment{0, c.radius[k], 0, pi, 0, 2 * pi}, {}, 0, ""};
    p.placement.translation = c.center[k];
    p.max_size = c.magnet_size;
    g.parts.push_back(p);
  }
  return g;
}

Mesh3D pair_mesh(const PairCase& c) {
  std::vector<ProbeSurface> refine;
  for (const V3& x : c.center)
    refine.push_back({x, c.stress_radius, 0, pi, 0, 2 * pi});
  return build_mesh_3d(pair_geometry(c), refine);
}

std::unique_ptr<PairSolution> solve_pair(const PairCase& c, const Mesh3D& mesh,
                                         const std::array<V3, 2>& direction) {
  const auto t0 = std::chrono::steady_clock::now();
  auto s = std::make_unique<PairSolution>();
  s->magnet = Material::make_magnet("magnet", c.B_r, 1.0, "test");
  s->mesh = mesh;
  s->problem.mesh = &s->mesh;
  s->problem.order = c.order;
  s->problem.boundary = OuterKind3D::open;
  s->problem.air.material = &s->air;
  for (const V3& d : direction) {
    Magnetization m;
    m.pattern = Magnetization::Pattern::parallel;
    m.direction = d.normalized();
    s->problem.parts.push_back({&s->magnet, m});
  }
  s->dofs = std::make_unique<DofMap3D>(s->mesh, c.order);
  s->dofs->curve_to_spheres(s->mesh, sphere_surfaces(pair_geometry(c), s->mesh));
  const Assembler3D assembler(s->problem, *s->dofs);
  NewtonOptions options;
  options.linear.kind = LinearSolverKind::cg;
  options.linear.cg_tolerance = 1e-10;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(assembler.n_unknowns());
  const NewtonReport report = solve_nonlinear(assembler, u, options);
  if (!report.converged)
    throw std::runtime_error("solve failed: " + report.message);
  s->n_unknowns = assembler.n_unknowns();
  s->field = std::make_unique<Field3D>(s->problem, *s->dofs, assembler.expand(u));
  s->locator = std::make_unique<PointLocator3D>(s->mesh);
  s->solve_s = seconds_since(t0);
  return s;
}

V3 moment(const PairCase& c, int k, const V3& direction) {
  return 4.0 / 3.0 * pi * std::pow(c.radius[k], 3) * c.B_r / mu0 * direction.normalized();
}

V3 dipole_B(const V3& m, const V3& r) {
  const double n = r.norm();
  const V3 u = r / n;
  return mu0 / (4 * pi * n * n * n) * (3 * u * u.dot(m) - m);
}

// Exact force on magnet k and torque about p.
ForceTorque exact_on(const PairCase& c, const std::array<V3, 2>& direction, int k, const V3& p) {
  const int o = 1 - k;
  const V3 mk = moment(c, k, direction[k]), mo = moment(c, o, direction[o]);
  const V3 r = c.center[k] - c.center[o];
  const double n = r.norm();
  const V3 u = r / n;
  ForceTorque ft;
  ft.force = 3 * mu0 / (4 * pi * std::pow(n, 4)) *
             (mo.dot(u) * mk + mk.dot(u) * mo + mo.dot(mk) * u - 5 * mo.dot(u) * mk.dot(u) * u);
  ft.torque = mk.cross(dipole_B(mo, r)) + (c.center[k] - p).cross(ft.force);
  return ft;
}

double force_error(const ForceTorque& a, const ForceTorque& exact) {
  return (a.force - exact.force).norm() / exact.force.norm();
}
double torque_error(const ForceTorque& a, const ForceTorque& exact) {
  return (a.torque - exact.torque).norm() / exact.torque.norm();
}

// Two relative orientations: parallel moments across the line of centres, and an oblique
// pair (non-zero force and torque components along every axis).
const std::array<std::array<V3, 2>, 2> orientations = {
    {{V3(0, 0, 1), V3(0.3, 0.8, -0.5)}, {V3(1, 0, 0), V3(-0.6, 0.2, 0.7)}}};

struct PairErrors {
  double force = 0, torque = 0; // worst relative error vs exact over magnets and orientations
  double radii = 0;             // worst relative difference between two stress radii
  double reaction = 0;          // worst |F_a + F_b| / |F|
  double torque_balance = 0;    // worst |T_a + T_b| about the origin / |T| about the centres
};

// Stress spheres about each magnet (torque about its centre, where the exact torque has no
// r x F part), at stress_radius, and at the two check_radii for the radius independence.
PairErrors pair_errors(const PairCase& c, const std::array<double, 2>& check_radii) {
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh3D mesh = pair_mesh(c);
  std::printf("mesh: %zu tets (%.1f s)\n", mesh.n_tets(), seconds_since(t0));
  PairErrors e;
  for (const auto& direction : orientations) {
    const auto s = solve_pair(c, mesh, direction);
    const FieldSampler3D B(*s->field, *s->locator);
    std::array<ForceTorque, 2> about_origin;
    for (int k = 0; k < 2; ++k) {
      const ForceTorque exact = exact_on(c, direction, k, c.center[k]);
      const ForceTorque ft = maxwell_stress_sphere_3d(B, c.center[k], c.stress_radius, c.center[k]);
      const ForceComparison radii = maxwell_stress_two_spheres_3d(B, c.center[k], check_radii[0],
                                                                  check_radii[1], c.center[k]);
      about_origin[k] = maxwell_stress_sphere_3d(B, c.center[k], c.stress_radius, V3::Zero());
      std::printf("%d unknowns, solved in %.1f s; magnet %d: |F| %.4f N, |T| %.5f N m; errors "
                  "force %.3f%%, torque %.3f%%; radii %.1f/%.1f mm differ by %.3f%% / %.3f%%\n",
                  s->n_unknowns, s->solve_s, k, exact.force.norm(), exact.torque.norm(),
                  100 * force_error(ft, exact), 100 * torque_error(ft, exact), check_radii[0] / mm,
                  check_radii[1] / mm, 100 * radii.force_rel_diff, 100 * radii.torque_rel_diff);
      e.force = std::max(e.force, force_error(ft, exact));
      e.torque = std::max(e.torque, torque_error(ft, exact));
      e.radii = std::max({e.radii, radii.force_rel_diff, radii.torque_rel_diff});
      // Surfaces through a magnet (its own, or the other one) measure nothing.
      EXPECT_THROW(maxwell_stress_sphere_3d(B, c.center[k], 7 * mm, c.center[k]),
                   std::invalid_argument);
      EXPECT_THROW(maxwell_stress_sphere_3d(B, c.center[k], 16 * mm, c.center[k]),
                   std::invalid_argument);
    }
    const ForceTorque net = about_origin[0] + about_origin[1];
    const double f_scale = exact_on(c, direction, 0, V3::Zero()).force.norm();
    const double t_scale = exact_on(c, direction, 0, c.center[0]).torque.norm();
    e.reaction = std::max(e.reaction, net.force.norm() / f_scale);
    e.torque_balance = std::max(e.torque_balance, net.torque.norm() / t_scale);
    std::printf("action + reaction: net force %.3f%%, net torque about the origin %.3f%%\n",
                100 * net.force.norm() / f_scale, 100 * net.torque.norm() / t_scale);
  }
  return e;
}

// The 0.5 % for force and torque, on the default (coarse) mesh: 254k unknowns, about
// 8 s per orientation. The stress sphere sits in the refined band (12.5 mm about each magnet
// of 8 mm; the other magnet is 14.4 mm away). Measured: force 0.11-0.19 %, torque about the
// centre 0.03-0.20 %, radii 12 vs 13 mm differ by up to 0.32 %, net force and torque of the
// pair up to 0.23 %; bounds are the 0.5 %. (Size scale 1.15: since the mesher no
// longer refines the air between the magnets and the domain boundary as a gap, scale 1.25
// gave 228k unknowns and a net torque of 0.53 %.) The error is larger nearer the magnet
// (11 mm: up to 0.45 % force), where its own field, which must cancel in the integral, is
// stronger relative to the other magnet's; it falls to <= 0.07 % (force, torque) and
// <= 0.15 % (radii 11 vs 13.5 mm) at 541k unknowns (LongFineMesh, ~1 min, long tier).
TEST(Force3D, TwoMagnetizedSpheresFeelTheExactDipoleForceAndTorque) {
  PairCase c;
  c.size_scale = 1.15;
  const PairErrors e = pair_errors(c, {12 * mm, 13 * mm});
  EXPECT_LT(e.force, 5e-3);
  EXPECT_LT(e.torque, 5e-3);
  EXPECT_LT(e.radii, 5e-3);
  EXPECT_LT(e.reaction, 5e-3);
  EXPECT_LT(e.torque_balance, 5e-3);
}

// The same on a finer mesh and at every radius of the gap from 11 to 13.5 mm (long tier).
// Written at 541k unknowns (size scale 0.8), measured then: force <= 0.066 %, torque <=
// 0.064 %, radii <= 0.15 %, net force <= 0.10 %, net torque <= 0.06 %; bounds about 3x that.
// The mesher has since stopped refining the air between a part and the boundary as a gap: at
// 0.8 it gave 517k unknowns and a net torque of 0.209 % (the long tier's first run failed
// here), so the scale is now 0.75 (604k unknowns, ~30 s per orientation). Measured at 0.75:
// force <= 0.121 %, torque <= 0.054 %, radii <= 0.134 %, net force <= 0.051 %, net torque
// <= 0.122 % (the remeshing noise of a pair 14 mm apart); the bounds are unchanged.
TEST(Force3D, LongFineMesh) {
  PairCase c;
  c.size_scale = 0.75;
  c.stress_radius = 12 * mm;
  const PairErrors e = pair_errors(c, {11 * mm, 13.5 * mm});
  EXPECT_LT(e.force, 2e-3);
  EXPECT_LT(e.torque, 2e-3);
  EXPECT_LT(e.radii, 4.5e-3);
  EXPECT_LT(e.reaction, 3e-3);
  EXPECT_LT(e.torque_balance, 2e-3);
}

// Element vs recovered sampling on the default mesh (long tier; prints the table): errors at
// four radii, and how much the result moves when the quadrature is refined. Asserted: both
// samplings meet the 0.5 % at every radius of the refined band (measured 0.06-0.50 %),
// and the default quadrature is converged: doubling it moves the force by less than 0.1 % with
// recovered sampling (the default; measured 3.4e-4) and 0.25 % with element sampling.
TEST(Force3D, LongSamplingStudy) {
  PairCase c;
  c.size_scale = 1.25;
  const Mesh3D mesh = pair_mesh(c);
  for (const auto& direction : orientations) {
    const auto s = solve_pair(c, mesh, direction);
    for (FieldSampling sampling : {FieldSampling::element, FieldSampling::recovered}) {
      const FieldSampler3D B(*s->field, *s->locator, sampling);
      for (int k = 0; k < 2; ++k) {
        const ForceTorque exact = exact_on(c, direction, k, c.center[k]);
        std::printf("%s magnet %d:", sampling == FieldSampling::element ? "element  " : "recovered",
                    k);
        for (double r : {11 * mm, 12 * mm, 12.5 * mm, 13 * mm}) {
          const ForceTorque ft = maxwell_stress_sphere_3d(B, c.center[k], r, c.center[k]);
          const ForceTorque coarse =
              maxwell_stress_sphere_3d(B, c.center[k], r, c.center[k], {48, 96});
          const ForceTorque fine =
              maxwell_stress_sphere_3d(B, c.center[k], r, c.center[k], {192, 384});
          std::printf(" r%.1f F %.3f%% T %.3f%% (48: %.1e, 192: %.1e)", r / mm,
                      100 * force_error(ft, exact), 100 * torque_error(ft, exact),
                      compare_force_torque(ft, coarse).force_rel_diff,
                      compare_force_torque(ft, fine).force_rel_diff);
          EXPECT_LT(force_error(ft, exact), 5e-3) << "r " << r / mm << " mm";
          EXPECT_LT(torque_error(ft, exact), 5e-3) << "r " << r / mm << " mm";
          // Element sampling is discontinuous across faces: its quadrature converges slower
          // (measured up to 1.6e-3 against 3.4e-4 recovered).
          EXPECT_LT(compare_force_torque(ft, fine).force_rel_diff,
                    sampling == FieldSampling::recovered ? 1e-3 : 2.5e-3)
              << "r " << r / mm;
        }
        std::printf("\n");
      }
    }
  }
}

} // namespace
} // namespace magfem

namespace magfem {
namespace {

// Torques about a point p off the origin and off both magnets, against the exact values
// m_k x B_o(c_k) + (c_k - p) x F_k, by the stress tensor on a sphere and on a box around each
// magnet. p = (5, -9, 6) mm makes the (c_k - p) x F part the larger share of the torque, so
// a torque point that is ignored, added instead of subtracted, or F x r instead of r x F is
// off by far more than the tolerance. Coarse mesh (size scale 3, chords of 1 mm on the
// spheres, one orientation: 26k unknowns, about a second); tolerances 3x the errors measured
// there (sphere 1.3 %, box 1.7 %; 0.2-0.5 % at 122k unknowns).
TEST(Force3DTorquePoint, ExactTorquesAboutAnOffOriginPoint) {
  PairCase c;
  c.size_scale = 3;
  c.chord = 1 * mm;
  const std::array<V3, 2> direction = orientations[1];
  const auto s = solve_pair(c, pair_mesh(c), direction);
  const FieldSampler3D B(*s->field, *s->locator);
  const V3 p(5 * mm, -9 * mm, 6 * mm);
  for (int k = 0; k < 2; ++k) {
    const ForceTorque exact = exact_on(c, direction, k, p);
    const ForceTorque sphere = maxwell_stress_sphere_3d(B, c.center[k], c.stress_radius, p);
    const ForceTorque box = maxwell_stress_box_3d(B, c.center[k], V3::Constant(19 * mm), p);
    std::printf("%d unknowns, %.1f s; magnet %d: torque about p %.5f N m ((c - p) x F part "
                "%.5f); errors: sphere %.3f%%, box %.3f%%\n",
                s->n_unknowns, s->solve_s, k, exact.torque.norm(),
                (c.center[k] - p).cross(exact.force).norm(), 100 * torque_error(sphere, exact),
                100 * torque_error(box, exact));
    EXPECT_LT(torque_error(sphere, exact), 5e-2);
    EXPECT_LT(torque_error(box, exact), 5e-2);
  }
}

} // namespace
} // namespace magfem
