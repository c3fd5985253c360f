// postproc/probe_error3d: the local field error of a tet from its energy-norm indicator, and
// the vertex-sharing rings around a probe's tets, on a three-tet chain whose answers are
// known by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "postproc/probe_error3d.hpp"

using namespace magfem;

namespace {

// Three unit right tets (volume 1/6 m^3) in a chain: t0 and t1 share the vertex 3, t1 and t2
// the vertex 6; t0 and t2 share none. t0, t1 air; t2 a linear region with mu_r = 4.
Mesh3D chain_mesh() {
  Mesh3D m;
  // corners: t0 {0,1,2,3}, t1 {3,4,5,6}, t2 {6,7,8,9} with 3, 6, 9 the apexes above
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
             {0, 1, 1}, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}, {0, 0, 3}};
  m.tets = {{0, 1, 2, 3}, {3, 4, 5, 6}, {6, 7, 8, 9}};
  m.tet_part = {-1, -1, 0};
  return m;
}

} // namespace

// e_K = sqrt(mu eta^2 / V) is the rms |B* - B_h| for a uniform difference dB over the tet:
// eta^2 = int (dB / mu) . dB dV = |dB|^2 V / mu. Exact to round-off. Planted: the 1/6 of the
// volume dropped reads sqrt(6) low; mu dropped, 1/sqrt(mu) high.
TEST(ProbeError3D, TetErrorIsTheRmsOfTheRecoveredDifference) {
  const Mesh3D mesh = chain_mesh();
  const Material air = Material::make_linear("air", 1.0, "test");
  const Material iron = Material::make_linear("iron", 4.0, "test");
  Problem3D problem;
  problem.mesh = &mesh;
  problem.air.material = &air;
  problem.parts = {RegionPhysics3D{&iron, {}}};
  const double volume = 1.0 / 6, dB = 0.01; // T
  const std::vector<double> eta2 = {dB * dB * volume / mu0, 4 * dB * dB * volume / mu0,
                                    dB * dB * volume / (4 * mu0)};
  const std::vector<double> e = tet_field_error_T(problem, eta2);
  EXPECT_NEAR(e[0], dB, 1e-12);
  EXPECT_NEAR(e[1], 2 * dB, 1e-12);
  EXPECT_NEAR(e[2], dB, 1e-12);
  EXPECT_NEAR(rms_over(e, {0, 1}), std::sqrt(2.5) * dB, 1e-12);
}

// Rings grow by vertex sharing only: t0 reaches t1 in one ring and t2 in two.
TEST(ProbeError3D, RingsGrowThroughSharedVertices) {
  const Mesh3D mesh = chain_mesh();
  EXPECT_EQ(tets_near(mesh, {0}, 0), (std::vector<std::size_t>{0}));
  EXPECT_EQ(tets_near(mesh, {0}, 1), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(tets_near(mesh, {0}, 2), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(tets_near(mesh, {2, 2}, 1), (std::vector<std::size_t>{1, 2}));
}
