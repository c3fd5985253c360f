#include "postproc/patch_recovery2d.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mesh/vertex_elements.hpp"
#include "postproc/patch_fit.hpp"
#include "solver/triangle_lagrange.hpp"

namespace magfem {
namespace {

using Fit = PatchFit<2>;
using Sample = Fit::Sample;

// The interior points of the degree-2 rule on a triangle (weights 1/3 of the area each).
const std::array<std::array<double, 3>, 3> rule_points = {
    {{2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, {1.0 / 6, 1.0 / 6, 2.0 / 3}}};

} // namespace

PatchRecovery2D::PatchRecovery2D(const Field2D& field) : field_(field) {
  const Problem2D& problem = field.problem();
  const Mesh2D& mesh = *problem.mesh;
  const DofMap2D& dofs = field.dofs();
  slots_ = RegionSlots(
      dofs.n_dofs(), mesh.n_triangles(), dofs.dofs_per_element(),
      [&](std::size_t t) { return dofs.element_dofs(t); },
      [&](std::size_t t) { return mesh.triangle_part[t]; });
  const VertexElements<3> around(mesh.triangles, mesh.n_nodes());

  auto add_samples = [&](int t, std::vector<Sample>& out) {
    const auto& k = mesh.triangles[t];
    const auto& p = mesh.nodes;
    const double area = 0.5 * std::abs((p[k[1]] - p[k[0]]).x() * (p[k[2]] - p[k[0]]).y() -
                                       (p[k[1]] - p[k[0]]).y() * (p[k[2]] - p[k[0]]).x());
    for (const auto& l : rule_points)
      out.push_back({field.point(t, l), field.B(t, l), area / 3});
  };

  // One fit per (vertex, region) slot of the vertex DOFs (DOFs 0 .. n_nodes - 1).
  const int degree = dofs.order();
  const int n_vertices = static_cast<int>(mesh.n_nodes());
  std::vector<Fit> fits(slots_.begin(n_vertices));
  std::vector<int> patch;
  std::vector<Sample> pts;
  for (int v = 0; v < n_vertices; ++v)
    for (int s = slots_.begin(v); s < slots_.end(v); ++s) {
      const int part = slots_.part(s);
      patch.clear();
      for (int t : around.of(v))
        if (mesh.triangle_part[t] == part)
          patch.push_back(t);
      if (static_cast<int>(patch.size()) < min_patch_triangles) {
        const std::vector<int> ring(patch);
        for (int t : ring)
          for (int w : mesh.triangles[t])
            for (int n : around.of(w))
              if (mesh.triangle_part[n] == part)
                patch.push_back(n);
        std::sort(patch.begin(), patch.end());
        patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
      }
      pts.clear();
      for (int t : patch)
        add_samples(t, pts);
      fits[s] = Fit::fit(pts, mesh.nodes[v], degree);
      if (fits[s].degree < degree)
        ++n_degraded_;
    }

  // Nodal values: a vertex its own fit, an edge node the mean of its two ends' fits there.
  value_.assign(slots_.size(), Eigen::Vector2d::Zero());
  for (int v = 0; v < n_vertices; ++v)
    for (int s = slots_.begin(v); s < slots_.end(v); ++s)
      value_[s] = fits[s].at(mesh.nodes[v]);
  if (dofs.order() >= 2)
    set_edge_values(fits);
  keep_axial_on_axis();
}

void PatchRecovery2D::set_edge_values(const std::vector<PatchFit<2>>& fits) {
  const Problem2D& problem = field_.problem();
  const Mesh2D& mesh = *problem.mesh;
  const DofMap2D& dofs = field_.dofs();
  std::vector<char> done(slots_.size(), 0);
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const int part = mesh.triangle_part[t];
    const int* dof = dofs.element_dofs(t);
    const auto& k = mesh.triangles[t];
    for (int e = 0; e < 3; ++e) {
      const int s = slots_.own_slot(dof[3 + e], part);
      if (done[s])
        continue;
      done[s] = 1;
      const Eigen::Vector2d& x = dofs.dof_points()[dof[3 + e]];
      value_[s] = 0.5 * (fits[slots_.own_slot(k[triangle_edges[e][0]], part)].at(x) +
                         fits[slots_.own_slot(k[triangle_edges[e][1]], part)].at(x));
    }
  }
}

void PatchRecovery2D::keep_axial_on_axis() {
  const Problem2D& problem = field_.problem();
  if (!problem.axisymmetric())
    return;
  for (int d : field_.dofs().dofs_on_edges(problem.mesh->axis_edges))
    for (int s = slots_.begin(d); s < slots_.end(d); ++s)
      value_[s].x() = 0;
}

Eigen::Vector2d PatchRecovery2D::B(std::size_t t, const std::array<double, 3>& bary) const {
  const DofMap2D& dofs = field_.dofs();
  std::array<double, 6> n{};
  const int count = triangle_values(dofs.order(), bary, n.data());
  const int* dof = dofs.element_dofs(t);
  const int part = field_.problem().mesh->triangle_part[t];
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (int i = 0; i < count; ++i)
    b += n[i] * value_[slots_.own_slot(dof[i], part)];
  return b;
}

} // namespace magfem
