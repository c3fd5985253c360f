// 2D probes in thin steel sheets and the air gaps between them (issue 30): a probe reads the
// element B of the triangle containing the point or its region's patch recovery, never the
// nodal average that VTU point data show (Field2D::recovered_B averages across region
// boundaries). Three sheets of mu_r 1000,
// 3.2 mm thick with 0.5 mm air gaps, in the uniform tangential field of a planar "solenoid":
// two 2 mm current layers (+J at the bottom, -J at the top) between ideal iron walls (natural
// boundaries everywhere: H_t = 0).
//
// Exact field: curl H = J gives dH_x/dy = -J_z, with H_x = 0 on the walls, so H_x = -J d
// everywhere between the layers, whatever the material; B_x = mu H_x jumps from -mu0 J d in air
// to -mu_r mu0 J d in steel, B_y = 0. A_z is quadratic in the current layers and linear
// between: P2 on a mesh whose cell faces lie on the layer faces contains it, so the solution is
// exact to the direct solver's round-off (~1e-10 of B with the 1000:1 contrast), and 1e-6 of
// the local |B| is a safe tolerance, far below the error of an average across a sheet face.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../solver/structured_mesh.hpp"
#include "core/constants.hpp"
#include "postproc/field2d.hpp"
#include "postproc/point_locator2d.hpp"
#include "postproc/probes2d.hpp"
#include "solver/assembler2d.hpp"
#include "solver/newton.hpp"

namespace magfem {
namespace {

constexpr double mm = 1e-3;
constexpr double mu_r = 1000;
constexpr double d = 2 * mm;                  // current layer thickness
constexpr double j0 = 1.0 / (mu0 * mu_r * d); // A/m^2: |B_x| = 1 T in steel, 1 mT in air
// Cell faces in y (mm): current layers [0, 2] and [24.6, 26.6]; sheets [8, 11.2], [11.7, 14.9],
// [15.4, 18.6], one cell thick each.
const std::vector<double> y_levels = {0, 2, 8, 11.2, 11.7, 14.9, 15.4, 18.6, 24.6, 26.6};

int sheet_of(double y) { // 0, 1, 2 bottom to top; -1 outside the sheets
  for (int k = 0; k < 3; ++k)
    if (y > y_levels[2 + 2 * k] * mm && y < y_levels[3 + 2 * k] * mm)
      return k;
  return -1;
}

TEST(ThinPlate2D, ProbesInSheetsAndGapsReadTheElementField) {
  const Material air = Material::make_linear("air", 1.0, "test");
  const Material steel = Material::make_linear("steel", mu_r, "test");
  const int ny = static_cast<int>(y_levels.size()) - 1;
  Mesh2D mesh = test::structured_rectangle(20 * mm, 26.6 * mm, 6, ny, 0);
  for (auto& p : mesh.nodes) // uniform levels -> the layer faces (monotone)
    p.y() = y_levels[std::lround(p.y() / (26.6 * mm) * ny)] * mm;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    double yc = 0;
    for (int k = 0; k < 3; ++k)
      yc += mesh.nodes[mesh.triangles[t][k]].y() / 3;
    // Parts: 0, 1 the current layers (bottom, top), 2 + k sheet k; gaps and the rest air.
    if (yc < d)
      mesh.triangle_part[t] = 0;
    else if (yc > y_levels[8] * mm)
      mesh.triangle_part[t] = 1;
    else
      mesh.triangle_part[t] = sheet_of(yc) >= 0 ? 2 + sheet_of(yc) : region_background;
  }
  Problem2D problem;
  problem.mesh = &mesh;
  problem.order = 2;
  problem.boundary = OuterKind::neumann;
  problem.air.material = &air;
  problem.parts = {
      {&air, {}, j0}, {&air, {}, -j0}, {&steel, {}, 0}, {&steel, {}, 0}, {&steel, {}, 0}};
  const DofMap2D dofs(mesh, 2);
  const Assembler2D assembler(problem, dofs);
  Eigen::VectorXd u;
  ASSERT_TRUE(solve_nonlinear(assembler, u, NewtonOptions{}).converged);
  const Field2D field(problem, dofs, assembler.expand(u));

  ProbeSpec probe;
  probe.name = "stack";
  probe.start = Eigen::Vector3d(7.3 * mm, 2.55 * mm, 0);
  probe.end = Eigen::Vector3d(7.3 * mm, 24.05 * mm, 0);
  probe.points = 44; // every 0.5 mm: in every sheet and gap, never on a face
  const PointLocator2D locator(mesh);
  const ProbeTable t = sample_probe_2d(field, locator, probe, mm);
  ASSERT_EQ(t.columns, (std::vector<std::string>{"x", "y", "Bx", "By"}));
  // The patch recovery (what `magfem solve` writes) fits a polynomial per region: the exact
  // field, constant in each sheet and gap and linear in the current layers, whatever the
  // patch shape, if no fit reaches across a face.
  const PatchRecovery2D recovery(field);
  const ProbeTable recovered = sample_probe_2d(field, locator, probe, mm, &recovery);
  int in_steel = 0, in_gaps = 0;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const auto& row = t.rows[k];
    const auto& rec = recovered.rows[k];
    const double y = row[1] * mm;
    const int sheet = sheet_of(y);
    in_steel += sheet >= 0;
    in_gaps += sheet < 0 && y > 11.2 * mm && y < 15.4 * mm;
    const Eigen::Vector2d exact(-(sheet >= 0 ? mu_r : 1.0) * mu0 * j0 * d, 0);
    EXPECT_LT((Eigen::Vector2d(row[2], row[3]) - exact).norm(), 1e-6 * exact.norm())
        << "y = " << row[1] << " mm: B = (" << row[2] << ", " << row[3] << ") T, exact ("
        << exact.transpose() << ") T";
    EXPECT_LT((Eigen::Vector2d(rec[2], rec[3]) - exact).norm(), 1e-6 * exact.norm())
        << "recovered at y = " << row[1] << " mm: B = (" << rec[2] << ", " << rec[3]
        << ") T, exact (" << exact.transpose() << ") T";
  }
  EXPECT_GE(in_steel, 15);
  EXPECT_GE(in_gaps, 1);
}

} // namespace
} // namespace magfem
