#include "postproc/error_estimate2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>

#include <Eigen/Dense>

#include "core/constants.hpp"
#include "solver/curl2d.hpp"
#include "solver/shell_transform.hpp"
#include "solver/triangle_lagrange.hpp"
#include "solver/triangle_quadrature.hpp"

namespace magfem {
namespace {

// Barycentric coordinates of the local DOF points (vertices, then edge midpoints), in the
// order of DofMap2D::element_dofs; midpoint 3 + k lies on the edge from vertex k to k + 1.
constexpr std::array<std::array<double, 3>, 6> dof_points = {
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}}};
// A patch of fewer elements than this (a corner, a boundary vertex) is grown by one ring:
// a least-squares fit needs more samples than coefficients from more than one element.
constexpr std::size_t min_patch_elements = 3;

double area_of(const Mesh2D& mesh, std::size_t t) {
  const auto& tri = mesh.triangles[t];
  return TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
}

// The polynomial B* of one vertex patch in local coordinates s = (x - centre) / scale:
// linear (order 1) or quadratic (order 2) in s, one column of coefficients per B component.
struct PatchFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double scale = 1;
  Eigen::Matrix<double, 6, 2> coef = Eigen::Matrix<double, 6, 2>::Zero();

  // Fixed size (no allocation in the hot loop); the quadratic terms are zero for order 1.
  static Eigen::Matrix<double, 6, 1> basis(int order, const Eigen::Vector2d& s) {
    Eigen::Matrix<double, 6, 1> p = Eigen::Matrix<double, 6, 1>::Zero();
    p.head<3>() << 1, s.x(), s.y();
    if (order > 1)
      p.tail<3>() << s.x() * s.x(), s.x() * s.y(), s.y() * s.y();
    return p;
  }
  Eigen::Vector2d operator()(int order, const Eigen::Vector2d& x) const {
    return coef.transpose() * basis(order, (x - centre) / scale);
  }
};

// Triangles around each vertex (CSR).
struct VertexTriangles {
  std::vector<int> start, items;
  explicit VertexTriangles(const Mesh2D& mesh) : start(mesh.n_nodes() + 1, 0) {
    for (const auto& tri : mesh.triangles)
      for (int v : tri)
        ++start[v + 1];
    for (std::size_t i = 1; i < start.size(); ++i)
      start[i] += start[i - 1];
    items.resize(start.back());
    std::vector<int> next(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int v : mesh.triangles[t])
        items[next[v]++] = static_cast<int>(t);
  }
};

// The region's triangles around vertex v, grown by one ring when too few.
std::vector<int> patch_of(const Mesh2D& mesh, const VertexTriangles& vt, int v, int part) {
  std::vector<int> patch;
  for (int k = vt.start[v]; k < vt.start[v + 1]; ++k)
    if (mesh.triangle_part[vt.items[k]] == part)
      patch.push_back(vt.items[k]);
  if (patch.size() >= min_patch_elements)
    return patch;
  const std::vector<int> ring = patch;
  for (int t : ring)
    for (int w : mesh.triangles[t])
      for (int k = vt.start[w]; k < vt.start[w + 1]; ++k)
        if (mesh.triangle_part[vt.items[k]] == part)
          patch.push_back(vt.items[k]);
  std::sort(patch.begin(), patch.end());
  patch.erase(std::unique(patch.begin(), patch.end()), patch.end());
  return patch;
}

// Superconvergent patch recovery (Zienkiewicz and Zhu 1992): a least-squares fit of one
// polynomial of the element's degree to B_h sampled at the quadrature points of every element
// of the patch, where B_h is most accurate. The fit stays within one region: across an
// interface B_t jumps by mu_r and a common polynomial would call the jump an error.
// B_h and the point at the sampling points of every element, computed once: each element is
// in the patches of its three vertices.
struct Samples {
  int per_element = 0;
  std::vector<Eigen::Vector2d> x, b; // [triangle * per_element + k]

  explicit Samples(const Field2D& field) {
    const auto& rule = triangle_rule(field.dofs().order() == 1 ? 1 : 2);
    const std::size_t n = field.problem().mesh->n_triangles();
    per_element = static_cast<int>(rule.size());
    x.reserve(n * rule.size());
    b.reserve(n * rule.size());
    for (std::size_t t = 0; t < n; ++t)
      for (const auto& q : rule) {
        x.push_back(field.point(t, q.bary));
        b.push_back(field.B(t, q.bary));
      }
  }
};

PatchFit fit_patch(const Mesh2D& mesh, int order, const Samples& samples,
                   const std::vector<int>& patch, const Vec2& centre) {
  PatchFit fit;
  fit.centre = centre;
  double reach = 0; // the patch's extent about the centre: scaled coordinates are O(1)
  for (int t : patch)
    for (int v : mesh.triangles[t])
      reach = std::max(reach, (mesh.nodes[v] - centre).norm());
  fit.scale = reach;
  Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 2> atb = Eigen::Matrix<double, 6, 2>::Zero();
  for (int t : patch)
    for (int k = t * samples.per_element; k < (t + 1) * samples.per_element; ++k) {
      const Eigen::Matrix<double, 6, 1> p =
          PatchFit::basis(order, (samples.x[k] - centre) / fit.scale);
      ata += p * p.transpose();
      atb += p * samples.b[k].transpose();
    }
  if (order > 1) {
    // A patch too small or too flat for the full quadratic (a sliver chain along a boundary)
    // keeps only its constant and linear terms rather than fitting noise.
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(ata);
    const double d_min = ldlt.vectorD().minCoeff(), d_max = ldlt.vectorD().maxCoeff();
    if (ldlt.info() == Eigen::Success && d_min > 1e-10 * d_max) {
      fit.coef = ldlt.solve(atb);
      return fit;
    }
  }
  const Eigen::LDLT<Eigen::Matrix3d> low(ata.topLeftCorner<3, 3>());
  fit.coef.topRows<3>() = low.solve(atb.topRows<3>());
  return fit;
}

// Fits per (vertex, region), built lazily: a vertex on an interface has one per side.
class Recovery {
public:
  explicit Recovery(const Field2D& field)
      : mesh_(*field.problem().mesh), order_(field.dofs().order()), samples_(field), vt_(mesh_),
        head_(mesh_.n_nodes(), -1) {}

  const PatchFit& at(int v, int part) {
    for (int k = head_[v]; k >= 0; k = entries_[k].next)
      if (entries_[k].part == part)
        return entries_[k].fit;
    entries_.push_back(
        {part, head_[v],
         fit_patch(mesh_, order_, samples_, patch_of(mesh_, vt_, v, part), mesh_.nodes[v])});
    head_[v] = static_cast<int>(entries_.size()) - 1;
    return entries_.back().fit;
  }

private:
  struct Entry {
    int part, next;
    PatchFit fit;
  };
  const Mesh2D& mesh_;
  int order_;
  Samples samples_;
  VertexTriangles vt_;
  std::vector<int> head_;
  std::deque<Entry> entries_; // a deque: at() hands out references that later pushes keep valid
};

// B* at the element's DOF points: a vertex takes its own patch's value, a midpoint the mean
// of its two vertices' patches (the usual SPR rule for quadratic elements).
std::array<Eigen::Vector2d, 6> recovered_at_dofs(const Field2D& field, Recovery& rec,
                                                 std::size_t t) {
  const auto& mesh = *field.problem().mesh;
  const int order = field.dofs().order();
  const int part = mesh.triangle_part[t];
  const auto& tri = mesh.triangles[t];
  std::array<Eigen::Vector2d, 6> b;
  for (int i = 0; i < 3; ++i)
    b[i] = rec.at(tri[i], part)(order, mesh.nodes[tri[i]]);
  if (order > 1)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d mid = field.point(t, dof_points[3 + k]);
      b[3 + k] =
          0.5 * (rec.at(tri[k], part)(order, mid) + rec.at(tri[(k + 1) % 3], part)(order, mid));
    }
  return b;
}

// (B* - B_h) . (H* - H_h) at x. In the open-boundary shell, whose coordinates stand for the
// whole exterior, the energy density carries the transformation's metric (as in energy2d.cpp).
double error_density(const Field2D& field, std::size_t t, const Eigen::Vector2d& x,
                     const Eigen::Vector2d& b_star, const Eigen::Vector2d& b_h) {
  const auto& problem = field.problem();
  const Eigen::Vector2d d = b_star - b_h;
  if (!problem.is_shell(t))
    return d.dot(field.H(t, x, b_star) - field.H(t, x, b_h));
  const ShellTransform shell{problem.mesh->shell_inner_radius, problem.mesh->shell_outer_radius};
  if (problem.axisymmetric())
    return nu0 * d.dot(shell.curl_metric_meridional(x) * d);
  const Eigen::Vector2d grad_a(-d.y(), d.x());
  return nu0 * grad_a.dot(shell.metric<2>(x) * grad_a);
}

// eta_K^2 of one element: B* interpolated in the element's own Lagrange space.
double element_eta2(const Field2D& field, Recovery& rec, std::size_t t) {
  const auto& problem = field.problem();
  const std::array<Eigen::Vector2d, 6> b_star_dof = recovered_at_dofs(field, rec, t);
  const double area = area_of(*problem.mesh, t);
  double eta2 = 0;
  // Degree 4: the integrand is a polynomial of degree 2p (exact for p = 2 in linear media).
  for (const auto& q : triangle_rule(4)) {
    std::array<double, 6> n{};
    const int count = triangle_values(field.dofs().order(), q.bary, n.data());
    Eigen::Vector2d b_star = Eigen::Vector2d::Zero();
    for (int i = 0; i < count; ++i)
      b_star += n[i] * b_star_dof[i];
    const Eigen::Vector2d x = field.point(t, q.bary);
    const Eigen::Vector2d b_h = field.B(t, q.bary);
    const double density = error_density(field, t, x, b_star, b_h);
    eta2 += q.weight * area * measure_2d(problem.symmetry, x) * density;
  }
  return eta2;
}

} // namespace

ErrorEstimate2D estimate_error_2d(const Field2D& field, double energy) {
  const auto& problem = field.problem();
  const auto& mesh = *problem.mesh;
  Recovery rec(field);
  ErrorEstimate2D out;
  out.eta2.assign(mesh.n_triangles(), 0.0);
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    out.eta2[t] = element_eta2(field, rec, t);
    out.total_eta2 += out.eta2[t];
  }
  if (energy > 0) {
    out.energy_error_pct = 100 * 0.5 * out.total_eta2 / energy;
    out.energy_norm_error_pct = 100 * std::sqrt(0.5 * out.total_eta2 / energy);
  }
  return out;
}

} // namespace magfem
