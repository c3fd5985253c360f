// The table of the coils' source field at the rule points (solver/source_field_table3d): every
// entry is the field at the point the assembler and Field3D integrate at (the mapped point in
// the shell), per coil; the sums use the coils' currents; the DOF values are those at the DOF
// points; and the table does not depend on the thread count. A wrong point (the shell map
// forgotten, a bary/node mix-up), a coil or component index swapped, or a current applied
// twice changes the entries by far more than the single-precision storage (6e-8 relative).
#include <gtest/gtest.h>

#include <cstring>

#include "solver/shell_transform.hpp"
#include "solver/source_field_table3d.hpp"
#include "solver/tet_quadrature.hpp"
#include "structured_mesh3d.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;

// Two "coils" with smooth fields that differ per coil and component (no symmetry that would
// hide a swapped index), at distinct currents.
class PolynomialField : public SourceField3D {
public:
  int n_coils() const override { return 2; }
  double current(int coil) const override { return coil == 0 ? 3.0 : -0.5; }
  double turns(int) const override { return 1; }
  Eigen::Vector3d H(const Eigen::Vector3d& x) const override {
    return current(0) * H_per_ampere(0, x) + current(1) * H_per_ampere(1, x);
  }
  Eigen::Vector3d H_per_ampere(int coil, const Eigen::Vector3d& x) const override {
    const Eigen::Vector3d s = x / mm;
    if (coil == 0)
      return {1 + s.x() * s.y(), 2 - s.z(), 0.5 * s.x() * s.x()};
    return {s.z() * s.z(), -3 + s.x(), s.y() * s.z() + 4};
  }
  Eigen::Vector3d J(const Eigen::Vector3d&) const override { return Eigen::Vector3d::Zero(); }
};

double relative(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return (a - b).norm() / std::max(b.norm(), 1e-300);
}

TEST(SourceFieldTable3D, EntriesAreTheFieldAtTheRulePointsAndTheDofPoints) {
  // 8^3 cubes, 6 tets each; tets whose centroid lies beyond 12 mm from the origin form the
  // shell (R1 12 mm, R2 30 mm), so both branches are sampled.
  Mesh3D mesh = test::structured_box({0, 0, 0}, {10 * mm, 10 * mm, 10 * mm}, 8);
  mesh.shell_inner_radius = 12 * mm;
  mesh.shell_outer_radius = 30 * mm;
  int n_shell = 0;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      c += 0.25 * mesh.nodes[mesh.tets[t][k]];
    const bool shell = c.norm() > 12 * mm;
    mesh.tet_part[t] = shell ? region_shell_3d : region_background_3d;
    n_shell += shell;
  }
  ASSERT_GT(n_shell, 100);
  Problem3D problem;
  problem.mesh = &mesh;
  problem.order = 2;
  const DofMap3D dofs(mesh, 2);
  const PolynomialField field;
  const SourceFieldTable3D table(problem, dofs, field, 1);
  const ShellTransform shell{mesh.shell_inner_radius, mesh.shell_outer_radius};
  const auto& rule = tet_rule(SourceFieldTable3D::rule_degree);

  double worst = 0;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    const auto& tet = mesh.tets[t];
    for (int q = 0; q < static_cast<int>(rule.size()); ++q) {
      const auto& b = rule[q].bary;
      Eigen::Vector3d x = b[0] * mesh.nodes[tet[0]] + b[1] * mesh.nodes[tet[1]] +
                          b[2] * mesh.nodes[tet[2]] + b[3] * mesh.nodes[tet[3]];
      if (problem.is_shell(t))
        x = shell.map(x);
      for (int k = 0; k < 2; ++k)
        worst = std::max(worst, relative(table.H_per_ampere(t, q, k), field.H_per_ampere(k, x)));
      // The sum may cancel between the coils: its rounding scales with the terms' sizes.
      const double terms =
          3.0 * field.H_per_ampere(0, x).norm() + 0.5 * field.H_per_ampere(1, x).norm();
      worst = std::max(worst, (table.H(t, q) - field.H(x)).norm() / terms);
      std::array<Eigen::Vector3d, 2> all;
      table.H_per_ampere(t, q, all.data());
      worst = std::max(worst, relative(all[1], field.H_per_ampere(1, x)));
    }
  }
  // Single-precision storage: 2^-24 = 6e-8 relative per component, sqrt(3) times that for a
  // vector's norm.
  EXPECT_LT(worst, 2e-7);

  // DOF values: at the DOF points of tets outside the shell, zero at DOFs of the shell alone.
  std::vector<unsigned char> outside(dofs.n_dofs(), 0);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    if (!problem.is_shell(t))
      for (int i = 0; i < dofs.dofs_per_element(); ++i)
        outside[dofs.element_dofs(t)[i]] = 1;
  double worst_dof = 0;
  int n_zero = 0;
  for (int d = 0; d < dofs.n_dofs(); ++d) {
    const Eigen::Vector3d& x = dofs.dof_points()[d];
    if (outside[d])
      worst_dof = std::max(worst_dof, (table.H_at_dof(d) - field.H(x)).norm() /
                                          (3.0 * field.H_per_ampere(0, x).norm() +
                                           0.5 * field.H_per_ampere(1, x).norm()));
    else
      n_zero += table.H_at_dof(d).isZero(0.0);
  }
  EXPECT_LT(worst_dof, 2e-7);
  EXPECT_GT(n_zero, 0);
  EXPECT_EQ(n_zero, std::count(outside.begin(), outside.end(), 0));

  // The same table on 3 threads, bit for bit (each entry is computed on its own).
  const SourceFieldTable3D threaded(problem, dofs, field, 3);
  ASSERT_EQ(threaded.bytes(), table.bytes());
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    for (int q = 0; q < static_cast<int>(rule.size()); ++q)
      for (int k = 0; k < 2; ++k)
        ASSERT_EQ(threaded.H_per_ampere(t, q, k), table.H_per_ampere(t, q, k)) << t << " " << q;
}

} // namespace
} // namespace magfem
