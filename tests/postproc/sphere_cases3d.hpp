#pragma once
// Concentric-sphere test problems for the 3D solver and postprocessing, with their exact
// solutions: a uniformly magnetized sphere (mu_r 1) alone or inside a linear permeable shell.
// Shared by the tests and the accuracy script (magfem_sphere3d_study).
#include <chrono>
#include <memory>
#include <numbers>

#include <Eigen/Dense>

#include "core/constants.hpp"
#include "mesh/mesher3d.hpp"
#include "postproc/field3d.hpp"
#include "solver/assembler3d.hpp"
#include "solver/newton.hpp"

namespace magfem::test {

constexpr double mm = 1e-3;

struct SphereCase {
  int order = 2;
  double magnet_radius = 10 * mm;
  double B_r = 1.0;
  double shell_inner = 0, shell_outer = 0; // permeable shell (0 = none)
  double shell_mu_r = 100;
  double domain_radius = 25 * mm; // open boundary: mapped shell from here to 1.5x
  double magnet_size = 2 * mm;    // element sizes
  double air_size = 4 * mm;
  double chord_tolerance = 0.02 * mm;
  double probe_radius = 0; // refine around this sphere (0 = none)
  double probe_size = 1 * mm;
  double size_scale = 1.0;
  LinearSolverKind solver = LinearSolverKind::cg;
  double cg_tolerance = 1e-10;
  bool curved = true; // isoparametric P2 on the spheres (DofMap3D::curve_to_spheres)
};

// Owns everything a solution refers to (the problem holds pointers into it).
struct SphereSolution {
  Material air = Material::make_linear("air", 1.0, "test");
  Material magnet;
  Material iron;
  Mesh3D mesh;
  Problem3D problem;
  std::unique_ptr<DofMap3D> dofs;
  std::unique_ptr<Assembler3D> assembler;
  std::unique_ptr<Field3D> field;
  NewtonReport report;
  double mesh_s = 0, setup_s = 0;
};

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

inline Geometry3D sphere_geometry(const SphereCase& c) {
  Geometry3D g;
  g.outer.kind = OuterKind3D::open;
  g.outer.radius = c.domain_radius;
  g.outer.shell_ratio = 1.5;
  g.options.default_size = c.air_size;
  g.options.chord_tolerance = c.chord_tolerance;
  g.options.size_scale = c.size_scale;
  g.options.probe_size = c.probe_radius > 0 ? c.probe_size : 0;
  const double full = std::numbers::pi, turn = 2 * std::numbers::pi;
  g.parts.push_back(
      {"magnet", SphericalSegment{0, c.magnet_radius, 0, full, 0, turn}, {}, c.magnet_size, ""});
  if (c.shell_outer > 0)
    g.parts.push_back({"shell",
                       SphericalSegment{c.shell_inner, c.shell_outer, 0, full, 0, turn},
                       {},
                       c.magnet_size,
                       ""});
  return g;
}

inline Mesh3D build_sphere_mesh(const SphereCase& c) {
  std::vector<ProbeSurface> refine;
  if (c.probe_radius > 0)
    refine.push_back(
        {Eigen::Vector3d::Zero(), c.probe_radius, 0, std::numbers::pi, 0, 2 * std::numbers::pi});
  return build_mesh_3d(sphere_geometry(c), refine);
}

// Solves the case on `mesh` (built by build_sphere_mesh from the same case; copied in).
inline std::unique_ptr<SphereSolution> solve_sphere_case(const SphereCase& c, const Mesh3D& mesh) {
  auto s = std::make_unique<SphereSolution>();
  s->magnet = Material::make_magnet("magnet", c.B_r, 1.0, "test");
  s->iron = Material::make_linear("shell", c.shell_mu_r, "test");
  s->mesh = mesh;
  const auto t0 = std::chrono::steady_clock::now();
  s->problem.mesh = &s->mesh;
  s->problem.order = c.order;
  s->problem.boundary = OuterKind3D::open;
  s->problem.air.material = &s->air;
  Magnetization m;
  m.pattern = Magnetization::Pattern::parallel;
  m.direction = Eigen::Vector3d::UnitZ();
  s->problem.parts.push_back({&s->magnet, m});
  if (c.shell_outer > 0)
    s->problem.parts.push_back({&s->iron, {}});
  s->dofs = std::make_unique<DofMap3D>(s->mesh, c.order);
  if (c.curved)
    s->dofs->curve_to_spheres(s->mesh, sphere_surfaces(sphere_geometry(c), s->mesh));
  s->assembler = std::make_unique<Assembler3D>(s->problem, *s->dofs);
  s->setup_s = seconds_since(t0);
  NewtonOptions options;
  options.linear.kind = c.solver;
  options.linear.cg_tolerance = c.cg_tolerance;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(s->assembler->n_unknowns());
  s->report = solve_nonlinear(*s->assembler, u, options);
  s->field = std::make_unique<Field3D>(s->problem, *s->dofs, s->assembler->expand(u));
  return s;
}

inline std::unique_ptr<SphereSolution> solve_sphere_case(const SphereCase& c) {
  const auto t0 = std::chrono::steady_clock::now();
  const Mesh3D mesh = build_sphere_mesh(c);
  const double mesh_s = seconds_since(t0);
  auto s = solve_sphere_case(c, mesh);
  s->mesh_s = mesh_s;
  return s;
}

// Exact field of a uniformly magnetized sphere (radius a, remanence B_r along z, mu_r 1).
inline Eigen::Vector3d sphere_exact_B(const Eigen::Vector3d& x, double a, double B_r) {
  const double r = x.norm();
  if (r < a)
    return Eigen::Vector3d(0, 0, 2.0 / 3.0 * B_r);
  // Dipole m = (4/3) pi a^3 B_r / mu0: B = mu0 / (4 pi) (3 (m.r) r / r^5 - m / r^3).
  const Eigen::Vector3d m(0, 0, 4.0 / 3.0 * pi * a * a * a * B_r / mu0);
  return mu0 / (4 * pi) * (3 * m.dot(x) * x / std::pow(r, 5) - m / std::pow(r, 3));
}

// Magnetized sphere (radius a, B_r along z, mu_r 1) inside a concentric shell b..c of mu_s.
// Potential phi = f(r) cos(theta) (H = -grad phi), with f = A r (r < a), C r + D / r^2 (air
// gap), E r + F / r^2 (shell), G / r^2 (outside). Continuity of phi and of B_r at r = a, b, c
// gives six equations for the six coefficients (B_r = -mu f' cos(theta), plus B_r cos(theta)
// inside the magnet).
struct ShellSphereExact {
  double a, b, c, mu_s, B_r;
  Eigen::Matrix<double, 6, 1> coef; // A, C, D, E, F, G

  ShellSphereExact(double a_, double b_, double c_, double mu_s_, double B_r_)
      : a(a_), b(b_), c(c_), mu_s(mu_s_), B_r(B_r_) {
    Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    // r = a: A a = C a + D / a^2 ;  -mu0 A + B_r = -mu0 (C - 2 D / a^3)
    m.row(0) << a, -a, -1 / (a * a), 0, 0, 0;
    m.row(1) << -mu0, mu0, -2 * mu0 / (a * a * a), 0, 0, 0;
    rhs[1] = -B_r;
    // r = b: C b + D / b^2 = E b + F / b^2 ;  (C - 2 D / b^3) = mu_s (E - 2 F / b^3)
    m.row(2) << 0, b, 1 / (b * b), -b, -1 / (b * b), 0;
    m.row(3) << 0, 1, -2 / (b * b * b), -mu_s, 2 * mu_s / (b * b * b), 0;
    // r = c: E c + F / c^2 = G / c^2 ;  mu_s (E - 2 F / c^3) = -2 G / c^3
    m.row(4) << 0, 0, 0, c, 1 / (c * c), -1 / (c * c);
    m.row(5) << 0, 0, 0, mu_s, -2 * mu_s / (c * c * c), 2 / (c * c * c);
    coef = m.fullPivLu().solve(rhs);
  }

  Eigen::Vector3d B(const Eigen::Vector3d& x) const {
    const double r = x.norm();
    const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
    if (r < a)
      return (-mu0 * coef[0] + B_r) * z;
    // H of (P r + Q / r^2) cos(theta): -P z - Q (z / r^3 - 3 z x / r^5)
    auto h = [&](double p, double q) {
      return Eigen::Vector3d(-p * z - q * (z / std::pow(r, 3) - 3 * x.z() * x / std::pow(r, 5)));
    };
    if (r < b)
      return mu0 * h(coef[1], coef[2]);
    if (r < c)
      return mu0 * mu_s * h(coef[3], coef[4]);
    return mu0 * h(0, coef[5]);
  }
};

} // namespace magfem::test
