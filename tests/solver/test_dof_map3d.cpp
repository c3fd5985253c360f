// Tests of the 3D DOF map against references written out here with std::map (no TetGen): the
// edge DOFs numbered in sorted vertex-pair order on a mesh whose vertices are shuffled, and
// curve_to_spheres moving exactly the edge nodes of interface and boundary faces that lie on
// a sphere. Both are identities: the comparisons are exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "solver/dof_map3d.hpp"
#include "solver/tet_lagrange.hpp"
#include "structured_mesh3d.hpp"

namespace magfem {
namespace {

// A structured box whose vertex numbers are shuffled: neighbouring vertices get unrelated
// numbers, as TetGen's do, so that edge buckets are filled in no particular order.
Mesh3D shuffled_box(int n, unsigned seed) {
  Mesh3D m = test::structured_box(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1), n);
  std::vector<int> perm(m.n_nodes());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
  std::vector<Eigen::Vector3d> nodes(m.n_nodes());
  for (std::size_t v = 0; v < perm.size(); ++v)
    nodes[perm[v]] = m.nodes[v];
  m.nodes = nodes;
  for (auto& t : m.tets)
    for (int& v : t)
      v = perm[v];
  for (auto& f : m.outer_faces)
    for (int& v : f)
      v = perm[v];
  return m;
}

TEST(DofMap3D, EdgeDofsAreNumberedInSortedVertexPairOrder) {
  const Mesh3D mesh = shuffled_box(5, 7);
  std::set<std::pair<int, int>> edges;
  for (const auto& t : mesh.tets)
    for (const auto& e : tet_edges)
      edges.insert({std::min(t[e[0]], t[e[1]]), std::max(t[e[0]], t[e[1]])});
  const std::vector<std::pair<int, int>> sorted(edges.begin(), edges.end());
  const int nv = static_cast<int>(mesh.n_nodes());

  const DofMap3D dofs(mesh, 2);
  ASSERT_EQ(dofs.n_vertices(), nv);
  ASSERT_EQ(dofs.n_dofs(), nv + static_cast<int>(sorted.size()));
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    const int d = nv + static_cast<int>(k);
    const auto [a, b] = dofs.edge_ends(d);
    EXPECT_EQ(a, sorted[k].first);
    EXPECT_EQ(b, sorted[k].second);
    EXPECT_EQ(dofs.dof_points()[d], 0.5 * (mesh.nodes[a] + mesh.nodes[b]));
  }
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    const int* dof = dofs.element_dofs(t);
    for (int i = 0; i < 4; ++i)
      EXPECT_EQ(dof[i], mesh.tets[t][i]);
    for (int e = 0; e < 6; ++e) {
      const int a = mesh.tets[t][tet_edges[e][0]], b = mesh.tets[t][tet_edges[e][1]];
      const auto it = std::lower_bound(sorted.begin(), sorted.end(),
                                       std::pair<int, int>(std::min(a, b), std::max(a, b)));
      EXPECT_EQ(dof[4 + e], nv + static_cast<int>(it - sorted.begin())) << t << " " << e;
    }
  }
}

// The box mapped onto a ball of radius 1 (x -> x |x|_inf / |x|_2), the inner cube |x|_inf <=
// 1/2 becoming part 0, a ball of radius 1/2: the outer faces lie on the unit sphere and the
// interface on the sphere of radius 1/2.
Mesh3D ball_with_core(int n) {
  Mesh3D m = shuffled_box(n, 11);
  for (auto& x : m.nodes)
    if (x.norm() > 0)
      x *= x.lpNorm<Eigen::Infinity>() / x.norm();
  for (std::size_t t = 0; t < m.n_tets(); ++t) {
    double r = 0;
    for (int v : m.tets[t])
      r = std::max(r, m.nodes[v].norm());
    m.tet_part[t] = r <= 0.5 + 1e-12 ? 0 : 1;
  }
  return m;
}

TEST(DofMap3D, CurvesExactlyTheEdgeNodesOfSphericalInterfacesAndBoundaries) {
  const Mesh3D mesh = ball_with_core(6);
  const std::vector<SphereSurface> spheres = {{Eigen::Vector3d::Zero(), 0.5},
                                              {Eigen::Vector3d::Zero(), 1.0}};
  // Reference: every face with its tets' parts; a face of one tet or of two parts is a
  // surface; its edge nodes go onto the sphere its three vertices lie on.
  std::map<std::array<int, 3>, std::vector<int>> faces;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<int, 3> k = {mesh.tets[t][(f + 1) % 4], mesh.tets[t][(f + 2) % 4],
                              mesh.tets[t][(f + 3) % 4]};
      std::sort(k.begin(), k.end());
      faces[k].push_back(mesh.tet_part[t]);
    }
  std::map<std::pair<int, int>, double> on_sphere; // edge -> radius
  for (const auto& [k, parts] : faces) {
    if (parts.size() == 2 && parts[0] == parts[1])
      continue;
    for (const auto& s : spheres) {
      const bool all = std::all_of(k.begin(), k.end(), [&](int v) {
        return std::abs(mesh.nodes[v].norm() - s.radius) <= 1e-9 * s.radius;
      });
      if (!all)
        continue;
      for (int e = 0; e < 3; ++e)
        on_sphere.emplace(std::minmax(k[e], k[(e + 1) % 3]), s.radius);
      break;
    }
  }
  ASSERT_GT(on_sphere.size(), 100u); // both spheres have many faces

  DofMap3D dofs(mesh, 2);
  dofs.curve_to_spheres(mesh, spheres);
  std::size_t moved = 0;
  for (int d = dofs.n_vertices(); d < dofs.n_dofs(); ++d) {
    const auto [a, b] = dofs.edge_ends(d);
    const Eigen::Vector3d mid = 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
    const Eigen::Vector3d x = dofs.dof_points()[d];
    if (x == mid)
      continue;
    ++moved;
    const auto it = on_sphere.find({a, b});
    ASSERT_NE(it, on_sphere.end()) << "edge node " << d << " moved off a sphere face";
    EXPECT_NEAR(x.norm(), it->second, 1e-14);
    EXPECT_EQ(x, it->second * mid / mid.norm());
  }
  // Every sphere edge node moved, except those kept straight to spare a folded tet.
  EXPECT_EQ(moved + dofs.n_straightened(), on_sphere.size());
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    bool any = false;
    for (int e = 4; e < 10; ++e) {
      const int d = dofs.element_dofs(t)[e];
      const auto [a, b] = dofs.edge_ends(d);
      any = any || dofs.dof_points()[d] != 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
    }
    EXPECT_EQ(dofs.is_curved(t), any) << t;
  }

  // More than 64 spheres (past the 64th they share one bit of a vertex's mask): the same
  // nodes, bit for bit.
  std::vector<SphereSurface> many(70, {Eigen::Vector3d(5, 0, 0), 0.25});
  many.insert(many.end(), spheres.begin(), spheres.end());
  DofMap3D again(mesh, 2);
  again.curve_to_spheres(mesh, many);
  EXPECT_EQ(again.dof_points(), dofs.dof_points());
  EXPECT_EQ(again.n_straightened(), dofs.n_straightened());
}

} // namespace
} // namespace magfem
