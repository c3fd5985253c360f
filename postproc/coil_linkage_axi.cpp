#include "postproc/coil_linkage_axi.hpp"

#include <stdexcept>

#include "solver/curl2d.hpp"
#include "solver/triangle_lagrange.hpp"
#include "solver/triangle_quadrature.hpp"

namespace magfem {

double flux_linkage_axi(const Field2D& field, int part, double turns) {
  const Problem2D& problem = field.problem();
  if (!problem.axisymmetric())
    throw std::invalid_argument("flux_linkage_axi: the field is planar");
  const Mesh2D& mesh = *problem.mesh;
  // r A_phi is a polynomial of degree order + 1 <= 3 per element: degree 4 integrates it exactly.
  const auto& rule = triangle_rule(4);
  double area = 0, flux = 0;
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    if (mesh.triangle_part[t] != part)
      continue;
    const auto& tri = mesh.triangles[t];
    const double a =
        TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
    area += a;
    for (const auto& q : rule)
      flux +=
          q.weight * a * measure_2d(problem.symmetry, field.point(t, q.bary)) * field.A(t, q.bary);
  }
  if (!(area > 0))
    throw std::invalid_argument("flux_linkage_axi: the part has no element");
  return turns / area * flux;
}

} // namespace magfem
