// Probes in thin steel sheets and the air gaps between them (issue 30): the recovered B a
// probe reads (nodal averages or patch recovery) must never mix materials. Three sheets of mu_r
// 1000, 3.2 mm thick with 0.5 mm air gaps (the stack), in a uniform oblique applied field
// H0 = (Hx, 0, Hz).
//
// Exact field: H tangential is continuous, so H_x = Hx everywhere and B_x jumps from mu0 Hx in
// air to mu_r mu0 Hx in steel; B normal is continuous, so B_z = mu0 Hz everywhere and H_z =
// Hz / mu_r in steel. The potential phi = -Hx x - integral_0^z H_z dz is continuous and
// linear in each layer: with a mesh whose cell faces lie on the sheet faces it is in the P1
// and P2 spaces, so the Galerkin solution is exact and the only error left is the direct
// solver's round-off (cond ~ 1e7 for the mu contrast and the 0.5 mm cells: ~1e-9 of B). The
// tolerance, 1e-6 of the local |B|, is far above that and far below what averaging across an
// interface does (B_x in a gap read as hundreds of times mu0 Hx; in a sheet, up to 15 % low).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "../solver/structured_mesh3d.hpp"
#include "core/constants.hpp"
#include "postproc/field3d.hpp"
#include "postproc/patch_recovery3d.hpp"
#include "postproc/point_locator3d.hpp"
#include "postproc/probes3d.hpp"
#include "postproc/recovered_b3d.hpp"
#include "solver/assembler3d.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;
constexpr double mu_r = 1000;
constexpr double hx = 1.0 / (mu0 * mu_r); // A/m: B_x = 1 T in steel, 1 mT in air
constexpr double hz = 0.01 / mu0;         // A/m: B_z = 10 mT everywhere
// Cell faces in z (mm): sheets [-5.3, -2.1], [-1.6, 1.6], [2.1, 5.3], one cell thick each.
const std::vector<double> z_levels = {-16, -10.3, -5.3, -2.1, -1.6, 1.6, 2.1, 5.3, 10.3, 16};

bool in_steel(double z) {
  const double a = std::abs(z);
  return a < 1.6 * mm || (a > 2.1 * mm && a < 5.3 * mm);
}

// phi = -hx x - integral_0^z H_z dz (A), for the layers above.
double phi_exact(const Eigen::Vector3d& p) {
  const double a = std::abs(p.z()) / mm;
  const double steel = std::min(a, 1.6) + std::clamp(a, 2.1, 5.3) - 2.1; // mm in steel
  return -hx * p.x() - std::copysign(hz * mm * ((a - steel) + steel / mu_r), p.z());
}

Eigen::Vector3d b_exact(double z) {
  return mu0 * Eigen::Vector3d(in_steel(z) ? mu_r * hx : hx, 0, hz);
}

struct SheetStack {
  Material air = Material::make_linear("air", 1.0, "test");
  Material steel = Material::make_linear("steel", mu_r, "test");
  Mesh3D mesh;
  Problem3D problem;
  std::unique_ptr<DofMap3D> dofs;
  std::unique_ptr<Field3D> field;

  explicit SheetStack(int order) {
    const int n = static_cast<int>(z_levels.size()) - 1;
    mesh = test::structured_box({-16 * mm, -16 * mm, -16 * mm}, {16 * mm, 16 * mm, 16 * mm}, n);
    for (auto& p : mesh.nodes) // uniform levels -> the sheet faces (monotone: tets stay positive)
      p.z() = z_levels[std::lround((p.z() / mm + 16) / 32 * n)] * mm;
    for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
      double zc = 0;
      for (int k = 0; k < 4; ++k)
        zc += 0.25 * mesh.nodes[mesh.tets[t][k]].z();
      // Steel sheets are regions 0, 1, 2 (bottom to top); the gaps and outside are air.
      mesh.tet_part[t] = in_steel(zc) ? 1 + (zc > 2 * mm) - (zc < -2 * mm) : region_background_3d;
    }
    problem.mesh = &mesh;
    problem.order = order;
    problem.boundary = OuterKind3D::dirichlet;
    problem.air.material = &air;
    problem.parts = {{&steel, {}}, {&steel, {}}, {&steel, {}}};
    dofs = std::make_unique<DofMap3D>(mesh, order);
    field = std::make_unique<Field3D>(problem, *dofs, solve());
  }

  // The potential with phi = phi_exact on the outer faces: K_ff u = -r_f(lift), where the lift
  // holds the boundary values (the problem is linear, so r(lift + u) = r(lift) + K u).
  Eigen::VectorXd solve() const {
    const Assembler3D assembler(problem, *dofs, {1, {}});
    const auto& eq = assembler.dof_to_equation();
    Eigen::VectorXd lift = Eigen::VectorXd::Zero(dofs->n_dofs());
    for (int d = 0; d < dofs->n_dofs(); ++d)
      if (eq[d] < 0)
        lift[d] = phi_exact(dofs->dof_points()[d]);
    const int m = dofs->dofs_per_element();
    Eigen::VectorXd r = Eigen::VectorXd::Zero(assembler.n_unknowns());
    std::vector<Eigen::Triplet<double>> k;
    std::array<double, 10> re{};
    std::array<double, 100> ke{};
    for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
      assembler.element(t, lift, re.data(), ke.data(), TangentKind::newton);
      const int* dof = dofs->element_dofs(t);
      for (int i = 0; i < m; ++i) {
        if (eq[dof[i]] < 0)
          continue;
        r[eq[dof[i]]] += re[i];
        for (int j = 0; j < m; ++j)
          if (eq[dof[j]] >= 0)
            k.emplace_back(eq[dof[i]], eq[dof[j]], ke[i * m + j]);
      }
    }
    Eigen::SparseMatrix<double> kff(assembler.n_unknowns(), assembler.n_unknowns());
    kff.setFromTriplets(k.begin(), k.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(kff);
    EXPECT_EQ(ldlt.info(), Eigen::Success);
    return lift + assembler.expand(ldlt.solve(-r));
  }
};

// The probe points (mm): the middle of the centre sheet (the 1.39 T point), off the
// middle and near its faces, two gap points, the outer sheets, and the air below the stack 0.2
// to 4 mm from the bottom sheet. Off-middle points matter: on this structured P2 mesh a point
// exactly halfway through a one-cell layer reads only the mid-edge nodes, which lie inside it.
std::vector<Eigen::Vector3d> probe_points() {
  std::vector<Eigen::Vector3d> pts;
  for (double z : {0.0, 0.3, 0.8, 1.5, -1.55, 1.75, -1.95, 3.7, -5.2, -5.5, -6.3, -7.5, -9.3})
    pts.push_back(Eigen::Vector3d(0.7, -1.3, z) * mm);
  return pts;
}

void check_probes(int order) {
  const SheetStack s(order);
  const PointLocator3D locator(s.mesh);
  const RecoveredB3D recovered(*s.field);
  ProbeSpec probe;
  probe.name = "stack";
  probe.kind = ProbeSpec::Kind::points;
  probe.point_list = probe_points();
  const ProbeTable element = sample_probe_3d(*s.field, locator, probe, mm);
  const ProbeTable rec = sample_probe_3d(*s.field, locator, probe, mm, &recovered);
  // The patch recovery (what `magfem solve` writes) fits a polynomial per region: the
  // constant B of each layer exactly, whatever the patch shape, if no fit reaches across.
  const PatchRecovery3D patch_recovery(*s.field);
  const ProbeTable patch = sample_probe_3d(*s.field, locator, probe, mm, patch_recovery);
  ASSERT_EQ(rec.columns.back(), "region_id");
  for (std::size_t k = 0; k < probe.point_list.size(); ++k) {
    const double z = probe.point_list[k].z();
    const Eigen::Vector3d exact = b_exact(z);
    const auto& row = rec.rows[k];
    const Eigen::Vector3d b_rec(row[3], row[4], row[5]);
    const Eigen::Vector3d b_el(element.rows[k][3], element.rows[k][4], element.rows[k][5]);
    const Eigen::Vector3d b_patch(patch.rows[k][3], patch.rows[k][4], patch.rows[k][5]);
    const double tol = 1e-6 * exact.norm();
    EXPECT_LT((b_patch - exact).norm(), tol)
        << "patch-recovered B at z = " << z / mm << " mm: (" << b_patch.transpose()
        << ") T, exact (" << exact.transpose() << ") T";
    EXPECT_LT((b_el - exact).norm(), tol) << "element B at z = " << z / mm << " mm";
    EXPECT_LT((b_rec - exact).norm(), tol)
        << "recovered B at z = " << z / mm << " mm: (" << b_rec.transpose() << ") T, exact ("
        << exact.transpose() << ") T";
    const int region = static_cast<int>(row[6]);
    EXPECT_EQ(region == region_background_3d, !in_steel(z)) << "z = " << z / mm << " mm";
  }
}

TEST(ThinPlate3D, ProbesInSheetsAndGapsReadTheirOwnRegionP1) {
  check_probes(1);
}
TEST(ThinPlate3D, ProbesInSheetsAndGapsReadTheirOwnRegionP2) {
  check_probes(2);
}

} // namespace
} // namespace magfem
