// Threaded element loops give the serial result bit for bit, whatever the thread count:
// the residual and tangent of the 3D assembly (nonlinear iron, a magnet, P2) and the
// recovered nodal B. Each sum is taken by one thread in element order
// (core/parallel_scatter.hpp); a race or a lost contribution at a block or ownership boundary
// changes the bits, and an atomic-add scheme would too (its order varies run to run).
#include <gtest/gtest.h>

#include <cstring>

#include "materials/material_library.hpp"
#include "postproc/field3d.hpp"
#include "postproc/recovered_b3d.hpp"
#include "solver/assembler3d.hpp"
#include "structured_mesh3d.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;

bool same_bits(const double* a, const double* b, std::size_t n) {
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}

TEST(ThreadedAssembly3D, ResidualTangentAndRecoveredBEqualTheSerialOnesBitForBit) {
  // 14^3 cubes, 6 tets each: 16,464 elements, more than one 4096-per-thread block for 2 and
  // 3 threads.
  Mesh3D mesh = test::structured_box({0, 0, 0}, {10 * mm, 10 * mm, 10 * mm}, 14);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
      c += 0.25 * mesh.nodes[mesh.tets[t][k]];
    mesh.tet_part[t] = c.z() < 5 * mm ? 0 : 1;
  }
  const Material air = Material::make_linear("air", 1.0, "test");
  const Material magnet = Material::make_magnet("magnet", 1.2, 1.05, "test");
  Problem3D problem;
  problem.mesh = &mesh;
  problem.order = 2;
  problem.boundary = OuterKind3D::dirichlet;
  problem.air.material = &air;
  Magnetization m;
  m.pattern = Magnetization::Pattern::parallel;
  m.direction = Eigen::Vector3d(1, 2, 3).normalized();
  problem.parts = {{&magnet, m}, {MaterialLibrary::bundled().find("steel_1010"), {}}};
  const DofMap3D dofs(mesh, 2);

  const Assembler3D serial(problem, dofs, {1, {}});
  // A potential that drives the steel into its knee: the Newton tangent's 2 mu' H H^T term
  // is non-zero.
  const Eigen::VectorXd u = 300.0 * Eigen::VectorXd::Random(serial.n_unknowns());
  Eigen::VectorXd r1;
  Eigen::SparseMatrix<double> k1;
  serial.evaluate(u, r1, &k1, TangentKind::newton);

  // The serial loop itself against the plain element-by-element sum.
  {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(serial.n_unknowns());
    Eigen::SparseMatrix<double> k = serial.pattern().zero_matrix();
    const Eigen::VectorXd phi = serial.expand(u);
    std::array<double, 10> re{};
    std::array<double, 100> ke{};
    for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
      serial.element(t, phi, re.data(), ke.data(), TangentKind::newton);
      for (int i = 0; i < 10; ++i)
        if (const int eq = serial.dof_to_equation()[dofs.element_dofs(t)[i]]; eq >= 0)
          r[eq] += re[i];
      serial.pattern().add(k, t, ke.data());
    }
    EXPECT_TRUE(same_bits(r.data(), r1.data(), r.size()));
    EXPECT_TRUE(same_bits(k.valuePtr(), k1.valuePtr(), k.nonZeros()));
  }

  const Field3D field(problem, dofs, serial.expand(u));
  // Two regions: the DOFs on z = 5 mm hold a value per region (RecoveredB3D's slots).
  const RecoveredB3D rec1(field, 1);
  ASSERT_GT(rec1.n_slots(), static_cast<std::size_t>(dofs.n_dofs()));
  const auto& b1 = rec1.values();
  for (int threads : {2, 3, 7}) {
    const Assembler3D threaded(problem, dofs, {threads, {}});
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> k;
    threaded.evaluate(u, r, &k, TangentKind::newton);
    EXPECT_TRUE(same_bits(r.data(), r1.data(), r.size())) << threads << " threads";
    ASSERT_EQ(k.nonZeros(), k1.nonZeros());
    EXPECT_TRUE(same_bits(k.valuePtr(), k1.valuePtr(), k.nonZeros())) << threads << " threads";
    const RecoveredB3D rec(field, threads);
    const auto& b = rec.values();
    ASSERT_EQ(b.size(), b1.size());
    EXPECT_TRUE(same_bits(b[0].data(), b1[0].data(), 3 * b.size())) << threads << " threads";
  }
}

} // namespace
} // namespace magfem
