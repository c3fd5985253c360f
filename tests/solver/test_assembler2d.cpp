#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "core/constants.hpp"
#include "solver/assembler2d.hpp"
#include "solver/newton.hpp"
#include "solver/shell_transform.hpp"
#include "structured_mesh.hpp"

using namespace magfem;

namespace {

Material linear(double mu_r) {
  Material m;
  m.name = "lin";
  m.kind = MaterialKind::linear;
  m.mu_r = mu_r;
  return m;
}

Problem2D problem_on(const Mesh2D& mesh, const Material& mat, int order, OuterKind boundary,
                     double j = 0) {
  Problem2D p;
  p.mesh = &mesh;
  p.order = order;
  p.boundary = boundary;
  p.air.material = &mat;
  p.parts = {RegionPhysics2D{&mat, {}, j}};
  return p;
}

Eigen::MatrixXd dense_full(const Eigen::SparseMatrix<double>& lower) {
  Eigen::MatrixXd d = Eigen::MatrixXd(lower);
  return d.selfadjointView<Eigen::Lower>();
}

} // namespace

TEST(Assembler2D, NeumannStiffnessHasConstantsInTheNullSpace) {
  // The full operator annihilates constants (B = curl A ignores them). With the gauge DOF
  // removed, only the rows coupled to it can have non-zero row sums.
  const auto mesh = test::structured_rectangle(0.01, 0.02, 6, 9, 0);
  const auto mat = linear(3.0);
  for (int order : {1, 2}) {
    const auto p = problem_on(mesh, mat, order, OuterKind::neumann);
    const DofMap2D dofs(mesh, order);
    const Assembler2D a(p, dofs);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> k;
    a.evaluate(Eigen::VectorXd::Constant(a.n_unknowns(), 7.0), r, &k, TangentKind::newton);
    const Eigen::MatrixXd kd = dense_full(k);
    EXPECT_LT((kd - kd.transpose()).norm(), 1e-12 * kd.norm());
    // Row sums of the reduced matrix equal minus the coupling to the removed gauge DOF,
    // which only touches DOF 0's neighbours: all other rows sum to zero.
    const Eigen::VectorXd rows = kd * Eigen::VectorXd::Ones(kd.rows());
    int nonzero_rows = 0;
    for (int i = 0; i < rows.size(); ++i)
      if (std::abs(rows[i]) > 1e-9 * kd.norm()) ++nonzero_rows;
    EXPECT_LE(nonzero_rows, order == 1 ? 3 : 8) << "order " << order;
  }
}

TEST(Assembler2D, SecondOrderReproducesAQuadraticPotentialExactly) {
  // A = x (w - x) solves -nu A'' = 2 nu = J with A = 0 at x = 0, w and dA/dn = 0 at y = 0, h.
  // P2 contains it, so the FE solution is exact to round-off.
  const double w = 0.02, h = 0.01, mu_r = 2.0;
  const double nu = 1.0 / (mu0 * mu_r);
  const auto mesh = test::structured_rectangle(w, h, 8, 4, test::left | test::right);
  const auto mat = linear(mu_r);
  for (int order : {2}) {
    const auto p = problem_on(mesh, mat, order, OuterKind::dirichlet, 2 * nu);
    const DofMap2D dofs(mesh, order);
    const Assembler2D a(p, dofs);
    Eigen::VectorXd u;
    const auto report = solve_nonlinear(a, u, NewtonOptions{});
    ASSERT_TRUE(report.converged);
    EXPECT_EQ(report.iterations, 1);
    const Eigen::VectorXd full = a.expand(u);
    double err = 0;
    for (int d = 0; d < dofs.n_dofs(); ++d) {
      const double x = dofs.dof_points()[d].x();
      err = std::max(err, std::abs(full[d] - x * (w - x)));
    }
    EXPECT_LT(err, 1e-12 * w * w) << "order " << order;
  }
}

TEST(Assembler2D, MagnetBetweenIdealWallsGivesTheExactRemanenceField) {
  // A slab magnet (mu_r = 1, M along y). With A = 0 on the x-faces (flux-tight walls: B_x = 0
  // there) the remanence load integrates to zero and the exact answer is B = 0. With natural
  // boundaries everywhere (H_t = 0: ideal iron walls short-circuiting the magnet) the exact
  // answer is H = 0, B = B_r y_hat, i.e. A = -B_r x with the gauge A = 0 at DOF 0 (x = 0).
  const double w = 0.01, h = 0.01;
  const auto mesh = test::structured_rectangle(w, h, 4, 4, test::left | test::right);
  Material pm;
  pm.kind = MaterialKind::magnet;
  pm.mu_r = 1.0;
  pm.B_r = 1.2;
  Problem2D p = problem_on(mesh, pm, 2, OuterKind::dirichlet);
  p.parts[0].magnetization.pattern = Magnetization::Pattern::parallel;
  p.parts[0].magnetization.direction = Eigen::Vector3d::UnitY();
  const DofMap2D dofs(mesh, 2);
  const Assembler2D a(p, dofs);
  Eigen::VectorXd u;
  ASSERT_TRUE(solve_nonlinear(a, u, NewtonOptions{}).converged);
  EXPECT_LT(u.cwiseAbs().maxCoeff(), 1e-14);
  Problem2D q = problem_on(mesh, pm, 2, OuterKind::neumann);
  q.parts[0].magnetization = p.parts[0].magnetization;
  const Assembler2D b(q, dofs);
  Eigen::VectorXd v;
  ASSERT_TRUE(solve_nonlinear(b, v, NewtonOptions{}).converged);
  const Eigen::VectorXd full = b.expand(v);
  double err = 0;
  for (int d = 0; d < dofs.n_dofs(); ++d)
    err = std::max(err, std::abs(full[d] + pm.B_r * dofs.dof_points()[d].x()));
  EXPECT_LT(err, 1e-12 * pm.B_r * w);
}

TEST(ShellTransform, MetricIsSymmetricPositiveAndMatchesTheRadialMap) {
  const ShellTransform s{0.1, 0.2};
  for (double r : {0.1, 0.13, 0.19, 0.1999}) {
    const Eigen::Vector2d x(r * std::cos(0.3), r * std::sin(0.3));
    const Eigen::Matrix2d t = s.metric<2>(x);
    EXPECT_LT((t - t.transpose()).norm(), 1e-12 * t.norm());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(t);
    EXPECT_GT(es.eigenvalues().minCoeff(), 0);
    // Radial eigenvalue f/(r f') = (R2 - r)/r, tangential r/(R2 - r).
    const Eigen::Vector2d e = x / r;
    EXPECT_NEAR(e.dot(t * e), (0.2 - r) / r, 1e-9 * (1 + (0.2 - r) / r));
  }
}
