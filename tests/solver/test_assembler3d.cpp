// Tests of the 3D scalar-potential assembly on structured box meshes (no TetGen): element
// properties (symmetry, constants in the null space, consistency of the tangent), exact
// reproduction of polynomial potentials, a permeable-block problem with a dense reference.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include "box_problem3d.hpp"
#include "core/constants.hpp"
#include "solver/assembler3d.hpp"
#include "solver/linear_solver.hpp"
#include "solver/newton.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"
#include "structured_mesh3d.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

// Integral of L1^a L2^b L3^c over the reference tet divided by its volume: 6 a! b! c! / (a+b+c+3)!.
TEST(TetQuadrature, ExactForItsDegree) {
  for (int degree : {1, 2, 5}) {
    for (int a = 0; a <= degree; ++a)
      for (int b = 0; a + b <= degree; ++b)
        for (int c = 0; a + b + c <= degree; ++c) {
          double sum = 0;
          for (const auto& q : tet_rule(degree))
            sum +=
                q.weight * std::pow(q.bary[1], a) * std::pow(q.bary[2], b) * std::pow(q.bary[3], c);
          const double exact =
              6 * factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
          EXPECT_NEAR(sum, exact, 1e-14) << degree << ": " << a << b << c;
        }
  }
}

TEST(TetLagrange, PartitionOfUnityAndNodality) {
  for (int order : {1, 2}) {
    std::array<double, 10> n{};
    for (int k = 0; k < tet_dofs(order); ++k) {
      tet_values(order, tet_dof_nodes[k], n.data());
      for (int i = 0; i < tet_dofs(order); ++i)
        EXPECT_NEAR(n[i], i == k ? 1.0 : 0.0, 1e-15);
    }
    const TetGeometry g = TetGeometry::of({0, 0, 0}, {1, 0.1, 0}, {0.2, 1, 0}, {0.1, 0.3, 0.9});
    std::array<Eigen::Vector3d, 10> grad;
    tet_gradients(order, g, {0.1, 0.2, 0.3, 0.4}, grad.data());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < tet_dofs(order); ++i)
      sum += grad[i];
    EXPECT_LT(sum.norm(), 1e-13);
  }
}

using Fixture = test::BoxProblem3D;

TEST(Assembler3D, ElementMatrixSymmetricWithConstantsInNullSpace) {
  for (int order : {1, 2}) {
    Fixture f(2, order, OuterKind3D::neumann);
    const DofMap3D dofs(*f.problem.mesh, order);
    const Assembler3D assembler(f.problem, dofs);
    const int n = dofs.dofs_per_element();
    std::array<double, 10> re{};
    std::array<double, 100> ke{};
    const Eigen::VectorXd phi = Eigen::VectorXd::Random(dofs.n_dofs());
    for (std::size_t t = 0; t < f.mesh.n_tets(); ++t) {
      assembler.element(t, phi, re.data(), ke.data(), TangentKind::newton);
      double scale = 0;
      for (int k = 0; k < n * n; ++k)
        scale = std::max(scale, std::abs(ke[k]));
      for (int i = 0; i < n; ++i) {
        double row = 0;
        for (int j = 0; j < n; ++j) {
          EXPECT_NEAR(ke[i * n + j], ke[j * n + i], 1e-14 * scale);
          row += ke[i * n + j];
        }
        EXPECT_NEAR(row, 0.0, 1e-12 * scale); // K * constant = 0
      }
    }
  }
}

// The global tangent of a linear problem is the derivative of the residual: r(u) = K u - f.
TEST(Assembler3D, ResidualIsLinearWithTheTangent) {
  Fixture f(3, 2, OuterKind3D::dirichlet);
  const DofMap3D dofs(*f.problem.mesh, 2);
  const Assembler3D assembler(f.problem, dofs);
  const Eigen::VectorXd u = Eigen::VectorXd::Random(assembler.n_unknowns());
  Eigen::VectorXd r0, r1;
  Eigen::SparseMatrix<double> k;
  assembler.evaluate(Eigen::VectorXd::Zero(assembler.n_unknowns()), r0, &k, TangentKind::newton);
  assembler.evaluate(u, r1, nullptr, TangentKind::newton);
  const Eigen::VectorXd ku = k.selfadjointView<Eigen::Lower>() * u;
  EXPECT_LT((r1 - r0 - ku).norm(), 1e-12 * r1.norm());
  EXPECT_GT(assembler.load_norm(), 0);
}

// load_norm() is |r(0)| however it is reached: on demand, or remembered from an evaluation at
// u = 0 (with the tangent, either kind), never from one elsewhere (remembering the first
// evaluation whatever its u, planted, fails the second check; seen, removed).
TEST(Assembler3D, LoadNormIsTheResidualNormAtZero) {
  Fixture f(3, 2, OuterKind3D::dirichlet);
  const DofMap3D dofs(*f.problem.mesh, 2);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(Assembler3D(f.problem, dofs).n_unknowns());
  Eigen::VectorXd r0;
  Assembler3D(f.problem, dofs).evaluate(zero, r0, nullptr, TangentKind::newton);
  ASSERT_GT(r0.norm(), 0);
  EXPECT_EQ(Assembler3D(f.problem, dofs).load_norm(), r0.norm()) << "on demand";
  {
    const Assembler3D assembler(f.problem, dofs);
    Eigen::VectorXd r;
    assembler.evaluate(Eigen::VectorXd::Random(zero.size()), r, nullptr, TangentKind::newton);
    EXPECT_EQ(assembler.load_norm(), r0.norm()) << "after an evaluation away from zero";
  }
  for (TangentKind kind : {TangentKind::newton, TangentKind::picard}) {
    const Assembler3D assembler(f.problem, dofs);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> k;
    assembler.evaluate(zero, r, &k, kind);
    EXPECT_EQ(assembler.load_norm(), r0.norm()) << "remembered from Newton's first evaluation";
  }
}

// P2 contains every quadratic potential: for a harmonic one (x^2 - y^2 + 3 yz + linear), the
// residual vanishes at every DOF not on the box boundary (no interior source), and its
// gradient evaluated from the interpolant is exact everywhere. (P1 interpolation of the same
// potential has an O(h) gradient error: control that the check can fail.)
TEST(Assembler3D, P2ReproducesHarmonicQuadratic) {
  Material air = Material::make_linear("air", 1.0, "test");
  Mesh3D mesh = test::structured_box({-2 * mm, 0, 1 * mm}, {3 * mm, 4 * mm, 6 * mm}, 4);
  Problem3D p;
  p.mesh = &mesh;
  p.air.material = &air;
  p.parts = {{&air, {}}};
  p.boundary = OuterKind3D::neumann;
  auto phi = [](const Eigen::Vector3d& x) {
    return (x.x() * x.x() - x.y() * x.y() + 3 * x.y() * x.z()) * 1e6 + 200 * x.x() - 50 * x.z();
  };
  auto grad_phi = [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(2e6 * x.x() + 200, (-2 * x.y() + 3 * x.z()) * 1e6, 3e6 * x.y() - 50);
  };
  for (int order : {1, 2}) {
    p.order = order;
    const DofMap3D dofs(mesh, order);
    const Assembler3D assembler(p, dofs);
    Eigen::VectorXd full(dofs.n_dofs());
    for (int d = 0; d < dofs.n_dofs(); ++d)
      full[d] = phi(dofs.dof_points()[d]) - phi(dofs.dof_points()[0]);
    Eigen::VectorXd r;
    assembler.evaluate(assembler.restrict_to_free(full), r, nullptr, TangentKind::newton);
    std::vector<bool> on_boundary(dofs.n_dofs(), false);
    for (int d : dofs.dofs_on_faces(mesh.outer_faces))
      on_boundary[d] = true;
    double max_interior = 0, max_all = 0;
    for (int d = 0; d < dofs.n_dofs(); ++d) {
      const int eq = assembler.dof_to_equation()[d];
      if (eq < 0)
        continue;
      max_all = std::max(max_all, std::abs(r[eq]));
      if (!on_boundary[d])
        max_interior = std::max(max_interior, std::abs(r[eq]));
    }
    if (order == 2) {
      EXPECT_LT(max_interior, 1e-12 * max_all);
    }
    double max_grad_error = 0, scale = 0;
    for (std::size_t t = 0; t < mesh.n_tets(); t += 7) {
      const auto& tet = mesh.tets[t];
      const auto g = TetGeometry::of(mesh.nodes[tet[0]], mesh.nodes[tet[1]], mesh.nodes[tet[2]],
                                     mesh.nodes[tet[3]]);
      const std::array<double, 4> bary = {0.1, 0.2, 0.3, 0.4};
      std::array<Eigen::Vector3d, 10> grad;
      tet_gradients(order, g, bary, grad.data());
      Eigen::Vector3d gh = Eigen::Vector3d::Zero(), x = Eigen::Vector3d::Zero();
      for (int i = 0; i < dofs.dofs_per_element(); ++i)
        gh += full[dofs.element_dofs(t)[i]] * grad[i];
      for (int k = 0; k < 4; ++k)
        x += bary[k] * mesh.nodes[tet[k]];
      max_grad_error = std::max(max_grad_error, (gh - grad_phi(x)).norm());
      scale = std::max(scale, grad_phi(x).norm());
    }
    if (order == 2)
      EXPECT_LT(max_grad_error, 1e-10 * scale);
    else
      EXPECT_GT(max_grad_error, 1e-2 * scale);
  }
}

// A non-uniformly magnetized magnet against iron, dirichlet box: the solve through
// solve_nonlinear (CHOLMOD) equals a dense LDLT solve of the same system, and CG agrees.
TEST(Assembler3D, LinearSolveMatchesDenseReferenceAndCg) {
  Fixture f(3, 2, OuterKind3D::dirichlet);
  const DofMap3D dofs(*f.problem.mesh, 2);
  const Assembler3D assembler(f.problem, dofs);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> k;
  assembler.evaluate(Eigen::VectorXd::Zero(assembler.n_unknowns()), r, &k, TangentKind::newton);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(k).selfadjointView<Eigen::Lower>();
  const Eigen::VectorXd reference = dense.ldlt().solve(-r);
  for (auto kind : {LinearSolverKind::cholmod, LinearSolverKind::cg}) {
    NewtonOptions options;
    options.linear.kind = kind;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(assembler.n_unknowns());
    const NewtonReport report = solve_nonlinear(assembler, u, options);
    EXPECT_TRUE(report.converged);
    EXPECT_LT((u - reference).norm(), 1e-8 * reference.norm());
  }
}

// One tet outside the unit sphere with a face on it (a 60 deg triangle) and its fourth vertex
// at height `height` above the face's centre along the outward normal. Curving moves the
// face's edge nodes out by the sagitta (~0.13 here) towards the fourth vertex.
Mesh3D tet_on_unit_sphere(double height) {
  const double s = std::sqrt(3.0) / 2;
  Mesh3D mesh;
  mesh.nodes = {{1, 0, 0}, {0.5, s, 0}, {0.5, s / 3, std::sqrt(2.0 / 3) * 1.0}};
  for (auto& p : mesh.nodes)
    p.normalize();
  const Eigen::Vector3d a = mesh.nodes[0], b = mesh.nodes[1], c = mesh.nodes[2];
  Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
  const Eigen::Vector3d centre = (a + b + c) / 3;
  if (normal.dot(centre) < 0)
    normal = -normal;
  mesh.nodes.push_back(centre + height * normal);
  mesh.tets = {{0, 1, 2, 3}};
  if (TetGeometry::of(mesh.nodes[0], mesh.nodes[1], mesh.nodes[2], mesh.nodes[3]).volume < 0)
    mesh.tets = {{1, 0, 2, 3}};
  mesh.tet_part = {0};
  return mesh;
}

// A coarse tet thin across a sphere folds when its edge nodes go onto the sphere (a sagitta
// larger than its height): det J < 0 at its face, an indefinite stiffness matrix and CG stopped
// with DIVERGED_INDEFINITE (seen on the actuator at --mesh-scale 2). Such edge nodes stay at
// their midpoints; a tet with room for the sagitta is curved as before.
TEST(CurvedTets, EdgeNodesThatWouldFoldTheirTetStayStraight) {
  const std::vector<SphereSurface> unit = {{Eigen::Vector3d::Zero(), 1.0}};
  {
    const Mesh3D thick = tet_on_unit_sphere(1.0);
    DofMap3D dofs(thick, 2);
    dofs.curve_to_spheres(thick, unit);
    EXPECT_TRUE(dofs.is_curved(0));
    EXPECT_EQ(dofs.n_straightened(), 0u);
    for (int d = 4; d < 10; ++d) { // the face's three edge nodes on the sphere, the rest not
      const double r = dofs.dof_points()[d].norm();
      const auto [a, b] = dofs.edge_ends(d);
      const bool on_face = a != 3 && b != 3;
      if (on_face)
        EXPECT_NEAR(r, 1.0, 1e-14);
      else
        EXPECT_GT(std::abs(r - 1.0), 1e-3);
    }
  }
  {
    const Mesh3D thin = tet_on_unit_sphere(0.05);
    DofMap3D dofs(thin, 2);
    dofs.curve_to_spheres(thin, unit);
    EXPECT_FALSE(dofs.is_curved(0));
    EXPECT_EQ(dofs.n_straightened(), 3u);
    for (int d = 4; d < 10; ++d) {
      const auto [a, b] = dofs.edge_ends(d);
      EXPECT_LT((dofs.dof_points()[d] - 0.5 * (thin.nodes[a] + thin.nodes[b])).norm(), 1e-15);
    }
  }
}

} // namespace
} // namespace magfem
