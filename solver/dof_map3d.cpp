#include "solver/dof_map3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <variant>

#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "solver/tet_lagrange.hpp"
#include "solver/tet_quadrature.hpp"

namespace magfem {
namespace {
long long edge_key(int a, int b) {
  if (a > b)
    std::swap(a, b);
  return (static_cast<long long>(a) << 32) | static_cast<unsigned>(b);
}
} // namespace

DofMap3D::DofMap3D(const Mesh3D& mesh, int order) : order_(order) {
  if (order != 1 && order != 2)
    throw std::invalid_argument("element order must be 1 or 2");
  n_vertices_ = static_cast<int>(mesh.n_nodes());
  points_ = mesh.nodes;
  n_dofs_ = n_vertices_;
  const int per = dofs_per_element();
  const std::size_t n_tets = mesh.n_tets();
  element_dofs_.resize(n_tets * per);
  for (std::size_t t = 0; t < n_tets; ++t)
    for (int i = 0; i < 4; ++i)
      element_dofs_[t * per + i] = mesh.tets[t][i];
  if (order == 1)
    return;
  number_edges(mesh);
}

// Edges numbered in sorted order of their vertex pair (a < b), as one sort of all 6 n_tets
// (key, slot) pairs would number them, but bucketed by the lower vertex first: a bucket holds
// about 7 edges, so sorting buckets is linear in the mesh and runs on all cores, where the
// one sort of 9.5 M pairs was a serial second of benchmark32's assembly stage.
void DofMap3D::number_edges(const Mesh3D& mesh) {
  const std::size_t n_tets = mesh.n_tets();
  const auto n_vertices = static_cast<std::size_t>(n_vertices_);
  std::vector<std::size_t> first(n_vertices + 1, 0); // bucket of vertex a: first[a]..first[a+1]
  for (const auto& tet : mesh.tets)
    for (const auto& e : tet_edges)
      ++first[std::min(tet[e[0]], tet[e[1]]) + 1];
  for (std::size_t a = 0; a < n_vertices; ++a)
    first[a + 1] += first[a];
  // (upper vertex, element slot) per element edge, in its lower vertex's bucket.
  std::vector<std::pair<int, std::size_t>> entries(first[n_vertices]);
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < n_tets; ++t)
      for (int e = 0; e < 6; ++e) {
        const int a = mesh.tets[t][tet_edges[e][0]], b = mesh.tets[t][tet_edges[e][1]];
        entries[next[std::min(a, b)]++] = {std::max(a, b), t * 10 + 4 + e};
      }
  }
  // Sorted buckets and each one's count of distinct edges; then the numbers, in vertex order.
  const int threads = element_loop_threads(n_tets);
  std::vector<int> n_edges(n_vertices + 1, 0);
  parallel_blocks(n_vertices, 4096, threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t a = lo; a < hi; ++a) {
      const auto begin = entries.begin() + static_cast<std::ptrdiff_t>(first[a]);
      const auto end = entries.begin() + static_cast<std::ptrdiff_t>(first[a + 1]);
      std::sort(begin, end);
      for (auto it = begin; it != end; ++it)
        if (it == begin || it->first != (it - 1)->first)
          ++n_edges[a + 1];
    }
  });
  for (std::size_t a = 0; a < n_vertices; ++a)
    n_edges[a + 1] += n_edges[a];
  const int n_edges_total = n_edges[n_vertices];
  edge_keys_.resize(static_cast<std::size_t>(n_edges_total));
  points_.resize(n_vertices + static_cast<std::size_t>(n_edges_total));
  n_dofs_ = n_vertices_ + n_edges_total;
  parallel_blocks(n_vertices, 4096, threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t a = lo; a < hi; ++a) {
      int k = n_edges[a] - 1;
      for (std::size_t i = first[a]; i < first[a + 1]; ++i) {
        const int b = entries[i].first;
        if (i == first[a] || b != entries[i - 1].first) {
          ++k;
          edge_keys_[static_cast<std::size_t>(k)] = edge_key(static_cast<int>(a), b);
          points_[n_vertices + static_cast<std::size_t>(k)] = 0.5 * (mesh.nodes[a] + mesh.nodes[b]);
        }
        element_dofs_[entries[i].second] = n_vertices_ + k;
      }
    }
  });
}

int DofMap3D::edge_dof(int a, int b) const {
  const long long k = edge_key(a, b);
  auto it = std::lower_bound(edge_keys_.begin(), edge_keys_.end(), k);
  if (it == edge_keys_.end() || *it != k)
    throw std::logic_error("edge not in mesh");
  return n_vertices_ + static_cast<int>(it - edge_keys_.begin());
}

std::vector<SphereSurface> sphere_surfaces(const Geometry3D& geometry, const Mesh3D& mesh) {
  std::vector<SphereSurface> out;
  for (const auto& part : geometry.parts)
    if (const auto* seg = std::get_if<SphericalSegment>(&part.shape)) {
      if (seg->r_inner > 0)
        out.push_back({part.placement.translation, seg->r_inner});
      out.push_back({part.placement.translation, seg->r_outer});
    }
  out.push_back({Eigen::Vector3d::Zero(), geometry.outer.radius});
  if (mesh.shell_outer_radius > 0)
    out.push_back({Eigen::Vector3d::Zero(), mesh.shell_outer_radius});
  return out;
}

void DofMap3D::curve_to_spheres(const Mesh3D& mesh, const std::vector<SphereSurface>& spheres) {
  if (order_ != 2)
    return;
  // Faces of the region interfaces and the outer boundary: those whose two tets differ in
  // part, or that have one tet. Sorting the face keys finds the pairs; only faces with all
  // three vertices on one sphere can be curved, so only those are sorted (a few percent of
  // the 4 n_tets faces; sorting all was a serial second of benchmark32's assembly stage).
  auto on_sphere = [&](int v, const SphereSurface& s) {
    return std::abs((mesh.nodes[v] - s.center).norm() - s.radius) <= 1e-9 * s.radius;
  };
  // Per vertex, the spheres it lies on as bits (spheres past the 64th share the last bit: a
  // face kept too many is rejected by the test below, never one too few).
  std::vector<std::uint64_t> sphere_bits(mesh.n_nodes(), 0);
  for (std::size_t v = 0; v < mesh.n_nodes(); ++v)
    for (std::size_t k = 0; k < spheres.size(); ++k)
      if (on_sphere(static_cast<int>(v), spheres[k]))
        sphere_bits[v] |= std::uint64_t{1} << std::min<std::size_t>(k, 63);
  struct FaceRef {
    std::array<int, 3> key;
    int part;
  };
  std::vector<FaceRef> faces;
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<int, 3> k = {mesh.tets[t][(f + 1) % 4], mesh.tets[t][(f + 2) % 4],
                              mesh.tets[t][(f + 3) % 4]};
      if ((sphere_bits[k[0]] & sphere_bits[k[1]] & sphere_bits[k[2]]) == 0)
        continue;
      std::sort(k.begin(), k.end());
      faces.push_back({k, mesh.tet_part[t]});
    }
  std::sort(faces.begin(), faces.end(),
            [](const FaceRef& a, const FaceRef& b) { return a.key < b.key; });
  std::vector<char> moved(n_dofs_, 0);
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key)
      ++j;
    const bool surface = j - i == 1 || faces[i].part != faces[i + 1].part;
    const auto& k = faces[i].key;
    i = j;
    if (!surface)
      continue;
    for (const auto& s : spheres) {
      if (!on_sphere(k[0], s) || !on_sphere(k[1], s) || !on_sphere(k[2], s))
        continue;
      for (int e = 0; e < 3; ++e) {
        const int d = edge_dof(k[e], k[(e + 1) % 3]);
        if (moved[d])
          continue;
        const Eigen::Vector3d r = points_[d] - s.center;
        points_[d] = s.center + s.radius * r / r.norm();
        moved[d] = 1;
      }
      break;
    }
  }
  mark_curved(mesh, moved);
  // Straighten the curved tets whose map folds or nearly does, until none is left: reverting
  // an edge node only takes its other tets back towards their straight (valid) shape, but
  // one of them may still be folded by another edge, hence the loop.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
      if (!curved_[t] || min_jacobian_ratio(t) >= min_curved_jacobian_ratio)
        continue;
      for (int e = 4; e < 10; ++e) {
        const int d = element_dofs_[t * 10 + e];
        if (!moved[d])
          continue;
        const auto [a, b] = edge_ends(d);
        points_[d] = 0.5 * (points_[a] + points_[b]);
        moved[d] = 0;
        ++n_straightened_;
      }
      changed = true;
    }
    mark_curved(mesh, moved);
  }
}

void DofMap3D::mark_curved(const Mesh3D& mesh, const std::vector<char>& moved) {
  const int per = dofs_per_element();
  curved_.assign(mesh.n_tets(), 0);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t)
    for (int e = 4; e < per; ++e)
      if (moved[element_dofs_[t * per + e]])
        curved_[t] = 1;
}

// det J of the isoparametric map over the straight tet's, least over the vertices, the edge
// nodes and the points of the degree-5 rule the assembler integrates with. det J is a cubic,
// so sampled points are not a proof of positivity: the margin covers what lies between them.
double DofMap3D::min_jacobian_ratio(std::size_t t) const {
  const int* dof = element_dofs(t);
  std::array<Eigen::Vector3d, 10> x;
  for (int i = 0; i < 10; ++i)
    x[i] = points_[dof[i]];
  std::array<Eigen::Vector3d, 10> straight = x;
  for (int e = 0; e < 6; ++e)
    straight[4 + e] = 0.5 * (x[tet_edges[e][0]] + x[tet_edges[e][1]]);
  const double volume = tet_iso_density(straight, {0.25, 0.25, 0.25, 0.25});
  double least = std::numeric_limits<double>::infinity();
  for (const auto& l : tet_dof_nodes)
    least = std::min(least, tet_iso_density(x, l) / volume);
  for (const TetQuadPoint& q : tet_rule(5))
    least = std::min(least, tet_iso_density(x, q.bary) / volume);
  return least;
}

std::size_t DofMap3D::n_curved() const {
  return static_cast<std::size_t>(std::count(curved_.begin(), curved_.end(), 1));
}

std::vector<int> DofMap3D::dofs_on_faces(const std::vector<std::array<int, 3>>& faces) const {
  std::vector<int> out;
  out.reserve(faces.size() * (order_ == 1 ? 3 : 6));
  for (const auto& f : faces) {
    out.insert(out.end(), f.begin(), f.end());
    if (order_ == 2)
      for (int k = 0; k < 3; ++k)
        out.push_back(edge_dof(f[k], f[(k + 1) % 3]));
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace magfem
