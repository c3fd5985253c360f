#include "postproc/vtu_export_revolved.hpp"

#include "postproc/vtu_cell_names.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {

VtuGrid make_vtu_revolved(const Field2D& field, const std::vector<int>& material_of_part,
                          int air_material, const std::vector<std::string>& material_names,
                          const std::vector<std::string>& region_names, int n_phi) {
  const auto& problem = field.problem();
  if (!problem.axisymmetric() || n_phi < 3)
    throw std::invalid_argument("make_vtu_revolved: an axisymmetric field and n_phi >= 3");
  const auto& mesh = *problem.mesh;
  const auto b_nodes = field.recovered_B(); // per DOF; mesh vertices are DOFs 0..n_nodes-1
  const int n_nodes = static_cast<int>(mesh.n_nodes());
  VtuGrid g;
  VtuArray a{"A_phi", 1, {}}, b{"B", 3, {}}, bm{"|B|", 1, {}};
  for (int k = 0; k < n_phi; ++k) {
    const double phi = 2 * pi * k / n_phi, c = std::cos(phi), s = std::sin(phi);
    for (int v = 0; v < n_nodes; ++v) {
      const Eigen::Vector2d& x = mesh.nodes[static_cast<std::size_t>(v)];
      g.points.emplace_back(x.x() * c, x.x() * s, x.y());
      const Eigen::Vector2d& bv = b_nodes[static_cast<std::size_t>(v)];
      a.values.push_back(field.a()[v]);
      b.values.insert(b.values.end(), {bv.x() * c, bv.x() * s, bv.y()});
      bm.values.push_back(bv.norm());
    }
  }
  g.point_data = {a, b, bm};
  VtuArray region{"region_id", 1, {}, VtuType::Int32},
      material{"material_id", 1, {}, VtuType::Int32}, bc{"|B|", 1, {}};
  constexpr int vtk_wedge = 13;
  const std::array<double, 3> centroid = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (problem.is_shell(t))
      continue;
    const auto& tri = mesh.triangles[t];
    const int part = mesh.triangle_part[t];
    const double b_mag = field.B(t, centroid).norm();
    for (int k = 0; k < n_phi; ++k) {
      const int k1 = (k + 1) % n_phi;
      for (const int v : tri)
        g.connectivity.push_back(k * n_nodes + v);
      for (const int v : tri)
        g.connectivity.push_back(k1 * n_nodes + v);
      g.offsets.push_back(static_cast<int>(g.connectivity.size()));
      g.cell_types.push_back(vtk_wedge);
      region.values.push_back(part);
      material.values.push_back(part >= 0 ? material_of_part[part] : air_material);
      bc.values.push_back(b_mag);
    }
  }
  g.cell_data = {region, material, bc};
  add_region_and_material_names(g, region_names, material_names);
  return g;
}

} // namespace magfem
