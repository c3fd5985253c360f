#include "mesh/spatial_order3d.hpp"

#include <cstddef>
#include <numeric>
#include <thread>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

namespace magfem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// The indices 0..n-1 of `points` in Hilbert order.
std::vector<std::size_t> hilbert_order(const std::vector<Point>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using Traits =
      CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Point>::const_type>;
  CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(points)),
                     CGAL::Hilbert_sort_median_policy());
  return order;
}

} // namespace

void order_spatially(Mesh3D& m) {
  std::vector<Point> points;
  points.reserve(m.nodes.size());
  for (const auto& x : m.nodes)
    points.emplace_back(x.x(), x.y(), x.z());
  // The tets' centroids do not depend on how the nodes are numbered (the same coordinates,
  // summed in the same order), so the two sorts are independent: the tets' runs on a thread
  // of its own beside the nodes' (each is a serial quarter second at benchmark32's size).
  std::vector<Point> centroids;
  centroids.reserve(m.tets.size());
  for (const auto& t : m.tets) {
    const Eigen::Vector3d c = (m.nodes[t[0]] + m.nodes[t[1]] + m.nodes[t[2]] + m.nodes[t[3]]) / 4;
    centroids.emplace_back(c.x(), c.y(), c.z());
  }
  std::vector<std::size_t> tet_order;
  std::thread tet_sort([&] { tet_order = hilbert_order(centroids); });
  std::vector<std::size_t> node_order;
  try {
    node_order = hilbert_order(points);
  } catch (...) {
    tet_sort.join();
    throw;
  }
  tet_sort.join();
  std::vector<int> new_index(m.nodes.size());
  std::vector<Eigen::Vector3d> nodes(m.nodes.size());
  for (std::size_t k = 0; k < node_order.size(); ++k) {
    new_index[node_order[k]] = static_cast<int>(k);
    nodes[k] = m.nodes[node_order[k]];
  }
  m.nodes = std::move(nodes);
  const auto remap = [&](auto& cells) {
    for (auto& cell : cells)
      for (int& v : cell)
        v = new_index[v];
  };
  remap(m.tets);
  remap(m.outer_faces);
  for (auto& faces : m.symmetry_faces)
    remap(faces);

  std::vector<std::array<int, 4>> tets(m.tets.size());
  std::vector<int> part(m.tet_part.size());
  for (std::size_t k = 0; k < tet_order.size(); ++k) {
    tets[k] = m.tets[tet_order[k]];
    part[k] = m.tet_part[tet_order[k]];
  }
  m.tets = std::move(tets);
  m.tet_part = std::move(part);
}

} // namespace magfem
