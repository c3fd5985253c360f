#include "postproc/probe_error3d.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/mesh_quality3d.hpp"
#include "mesh/vertex_tets3d.hpp"
#include "postproc/point_locator3d.hpp"

namespace magfem {

std::vector<double> tet_field_error_T(const Problem3D& problem, const std::vector<double>& eta2_J) {
  const Mesh3D& mesh = *problem.mesh;
  std::vector<double> e(mesh.n_tets(), 0.0);
  for (std::size_t t = 0; t < mesh.n_tets(); ++t) {
    if (problem.is_shell(t))
      continue;
    const auto& k = mesh.tets[t];
    // The straight tet's volume: curved (P2) tets differ from it by the chord error only.
    const double volume = std::abs(
        tet_volume(mesh.nodes[k[0]], mesh.nodes[k[1]], mesh.nodes[k[2]], mesh.nodes[k[3]]));
    const double mu = problem.physics(mesh.tet_part[t]).material->start_permeability();
    if (volume > 0)
      e[t] = std::sqrt(mu * std::max(eta2_J[t], 0.0) / volume);
  }
  return e;
}

std::vector<TetPoint3D> locate_points(const Mesh3D& mesh,
                                      const std::vector<Eigen::Vector3d>& points) {
  const PointLocator3D locator(mesh);
  std::vector<TetPoint3D> out;
  out.reserve(points.size());
  for (const auto& x : points)
    if (const auto loc = locator.locate(x)) {
      // The barycentric weights place the point in the model's half of a cut mesh too.
      Eigen::Vector3d in_model = Eigen::Vector3d::Zero();
      for (int i = 0; i < 4; ++i)
        in_model += loc->bary[i] * mesh.nodes[mesh.tets[loc->tet][i]];
      out.push_back({loc->tet, in_model});
    }
  return out;
}

std::vector<std::size_t> tets_at_points(const Mesh3D& mesh,
                                        const std::vector<Eigen::Vector3d>& points) {
  std::vector<std::size_t> out;
  for (const TetPoint3D& p : locate_points(mesh, points))
    out.push_back(p.tet);
  return out;
}

std::vector<std::size_t> tets_near(const Mesh3D& mesh, const std::vector<std::size_t>& seeds,
                                   int rings) {
  // A ring is every tet touching a vertex of the last one.
  const VertexTets3D around(mesh);
  std::vector<char> in(mesh.n_tets(), 0);
  std::vector<std::size_t> front;
  for (std::size_t t : seeds)
    if (!in[t]) {
      in[t] = 1;
      front.push_back(t);
    }
  std::vector<std::size_t> out = front;
  for (int r = 0; r < rings; ++r) {
    std::vector<std::size_t> next;
    for (std::size_t t : front)
      for (int v : mesh.tets[t])
        for (int n : around.of(v))
          if (!in[n]) {
            in[n] = 1;
            next.push_back(std::size_t(n));
          }
    out.insert(out.end(), next.begin(), next.end());
    front = std::move(next);
  }
  std::sort(out.begin(), out.end());
  return out;
}

double rms_over(const std::vector<double>& e, const std::vector<std::size_t>& tets) {
  double sum = 0;
  for (std::size_t t : tets)
    sum += e[t] * e[t];
  return tets.empty() ? 0.0 : std::sqrt(sum / double(tets.size()));
}

} // namespace magfem
