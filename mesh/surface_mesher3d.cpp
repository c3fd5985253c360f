#include "mesh/surface_mesher3d.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "mesh/face_chart3d.hpp"
#include "mesh/mesh_error.hpp"

namespace magfem {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexInfo {
  int id = -1; // surface point index, -1 for points the 2D mesher inserted
};
using Vb =
    CGAL::Delaunay_mesh_vertex_base_2<K,
                                      CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Point2 = K::Point_2;

// Shape bound of the 2D refinement: B = sin^2 of the smallest angle, 0.125 ~ 20.7 deg (the
// value for which Delaunay refinement is guaranteed to terminate).
constexpr double shape_bound = 0.125;
// Integration step along curves as a fraction of the local size.
constexpr double curve_step = 0.2;

// Points merged by position (curve end points are computed from several curves).
class PointPool {
public:
  PointPool(std::vector<Vec3>& points, double tol) : points_(points), tol_(tol) {}
  int insert(const Vec3& x) {
    const Key k = key(x);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(Key{k.i + dx, k.j + dy, k.k + dz});
          if (it == cells_.end())
            continue;
          for (int id : it->second)
            if ((points_[id] - x).norm() <= tol_)
              return id;
        }
    const int id = static_cast<int>(points_.size());
    points_.push_back(x);
    cells_[k].push_back(id);
    return id;
  }

private:
  struct Key {
    long long i, j, k;
    bool operator==(const Key& o) const { return i == o.i && j == o.j && k == o.k; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::hash<long long>()(k.i * 73856093LL ^ k.j * 19349663LL ^ k.k * 83492791LL);
    }
  };
  Key key(const Vec3& x) const {
    return {static_cast<long long>(std::floor(x.x() / tol_)),
            static_cast<long long>(std::floor(x.y() / tol_)),
            static_cast<long long>(std::floor(x.z() / tol_))};
  }
  std::vector<Vec3>& points_;
  double tol_;
  std::unordered_map<Key, std::vector<int>, Hash> cells_;
};

// A grid edge: along `axis` over cell `cell`, at breakpoints fixed[0], fixed[1] of the other
// two axes taken in increasing axis order.
struct EdgeKey {
  int frame, axis, cell;
  std::array<int, 2> fixed;
  bool operator<(const EdgeKey& o) const {
    return std::tie(frame, axis, cell, fixed) < std::tie(o.frame, o.axis, o.cell, o.fixed);
  }
};

class CurveCache {
public:
  CurveCache(const GridDecomposition3D& dec, const SizeField3D& size, PointPool& pool)
      : dec_(dec), size_(size), pool_(pool) {}

  // Point ids from the lower to the upper end of the edge.
  const std::vector<int>& edge(const EdgeKey& key) {
    auto it = cache_.find(key);
    if (it == cache_.end())
      it = cache_.emplace(key, divide(key)).first;
    return it->second;
  }

private:
  // Divides the curve so that consecutive points are about h apart: integrates 1/h along it
  // and places points at equal increments of the integral.
  std::vector<int> divide(const EdgeKey& key) const {
    const GridFrame3D& f = dec_.frames[key.frame];
    Vec3 q;
    int n = 0;
    for (int a = 0; a < 3; ++a)
      if (a != key.axis)
        q[a] = f.breaks[a][key.fixed[n++]];
    const double lo = f.lo(key.axis, key.cell), hi = f.hi(key.axis, key.cell);
    auto at = [&](double t) {
      Vec3 qq = q;
      qq[key.axis] = t;
      return f.point(qq);
    };
    const Vec3 a = at(lo), b = at(hi), m = at(0.5 * (lo + hi));
    if ((a - b).norm() + (a - m).norm() < 1e-12 * (1 + a.norm()))
      return {pool_.insert(a)};
    std::vector<double> ts{lo}, integral{0};
    double t = lo;
    Vec3 x = a;
    const double dt_probe = 1e-7 * (hi - lo);
    while (t < hi) {
      const double h = size_(x);
      const double speed =
          (at(std::min(t + dt_probe, hi)) - at(std::min(t + dt_probe, hi) - dt_probe)).norm() /
          dt_probe;
      const double dt = std::min(hi - t, curve_step * h / std::max(speed, 1e-300));
      const double t_next = t + dt;
      const Vec3 x_next = at(t_next);
      const double h_next = size_(x_next);
      integral.push_back(integral.back() + (x_next - x).norm() * 0.5 * (1 / h + 1 / h_next));
      ts.push_back(t_next);
      t = t_next;
      x = x_next;
    }
    const int n_seg = std::max(1, static_cast<int>(std::ceil(integral.back() - 1e-6)));
    std::vector<int> ids{pool_.insert(a)};
    std::size_t s = 0;
    for (int k = 1; k < n_seg; ++k) {
      const double target = integral.back() * k / n_seg;
      while (integral[s + 1] < target)
        ++s;
      const double w = (target - integral[s]) / (integral[s + 1] - integral[s]);
      ids.push_back(pool_.insert(at(ts[s] + w * (ts[s + 1] - ts[s]))));
    }
    ids.push_back(pool_.insert(b));
    return ids;
  }

  const GridDecomposition3D& dec_;
  const SizeField3D& size_;
  PointPool& pool_;
  std::map<EdgeKey, std::vector<int>> cache_;
};

// Closed boundary loop of a face: its four grid edges, degenerate ones collapsing to a point.
std::vector<int> face_loop(const GridDecomposition3D& dec, const GridFace3D& face,
                           CurveCache& curves) {
  const GridFrame3D& f = dec.frames[face.frame];
  const int b1 = face.free_axis(0), b2 = face.free_axis(1);
  auto next_break = [&](int axis, int cell) {
    return f.periodic[axis] ? (cell + 1) % f.n_cells(axis) : cell + 1;
  };
  // Edge along `along` over `cell` with the other free axis at breakpoint `at_break`.
  auto edge = [&](int along, int cell, int other, int at_break) -> const std::vector<int>& {
    std::array<int, 3> idx{};
    idx[face.axis] = face.index;
    idx[other] = at_break;
    // A curve on a polar axis (spherical r-line at theta = 0 or pi, cylindrical z-line at
    // rho = 0) is the same curve for every angle: give it one key so it is divided once.
    if (f.kind == GridKind3D::spherical && along == 0) {
      const double theta = f.breaks[1][idx[1]];
      if (theta <= 0 || theta >= std::numbers::pi - 1e-9)
        idx[2] = 0;
    }
    if (f.kind == GridKind3D::cylindrical && along == 2 && f.breaks[0][idx[0]] <= 0)
      idx[1] = 0;
    std::array<int, 2> fixed{};
    int n = 0;
    for (int a = 0; a < 3; ++a)
      if (a != along)
        fixed[n++] = idx[a];
    return curves.edge({face.frame, along, cell, fixed});
  };
  const int c1 = face.cells[0], c2 = face.cells[1];
  const std::vector<int>* sides[4] = {&edge(b1, c1, b2, c2), &edge(b2, c2, b1, next_break(b1, c1)),
                                      &edge(b1, c1, b2, next_break(b2, c2)), &edge(b2, c2, b1, c1)};
  std::vector<int> loop;
  auto append = [&](int id) {
    if (loop.empty() || loop.back() != id)
      loop.push_back(id);
  };
  for (int id : *sides[0])
    append(id);
  for (int id : *sides[1])
    append(id);
  for (auto it = sides[2]->rbegin(); it != sides[2]->rend(); ++it)
    append(*it);
  for (auto it = sides[3]->rbegin(); it != sides[3]->rend(); ++it)
    append(*it);
  while (loop.size() > 1 && loop.front() == loop.back())
    loop.pop_back();
  return loop;
}

// Delaunay refinement criteria: a triangle is too big when its longest edge, measured on the
// surface (chords in 3D), exceeds h at its centroid; shape is judged in the chart, which is
// conformal or isometric.
class SurfaceCriteria : public CGAL::Delaunay_mesh_criteria_2<Cdt> {
public:
  using Base = CGAL::Delaunay_mesh_criteria_2<Cdt>;
  struct Quality : std::pair<double, double> {
    Quality() = default;
    const double& size() const { return second; }
    const double& sine() const { return first; }
    bool operator<(const Quality& q) const {
      if (size() > 1)
        return q.size() > 1 ? size() > q.size() : true;
      if (q.size() > 1)
        return false;
      return sine() < q.sine();
    }
  };
  class Is_bad : public Base::Is_bad {
  public:
    Is_bad(const FaceChart3D& chart, const SizeField3D& size)
        : Base::Is_bad(shape_bound, K()), chart_(&chart), size_(&size) {}
    CGAL::Mesh_2::Face_badness operator()(const Quality& q) const {
      if (q.size() > 1)
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }
    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& fh, Quality& q) const {
      Vec3 x[3];
      Eigen::Vector2d p[3];
      for (int i = 0; i < 3; ++i) {
        const Point2& pt = fh->vertex(i)->point();
        p[i] = {pt.x(), pt.y()};
        x[i] = chart_->to_3d(p[i]);
      }
      double l3 = 0;
      for (int i = 0; i < 3; ++i)
        l3 = std::max(l3, (x[i] - x[(i + 1) % 3]).norm());
      const double h = (*size_)((x[0] + x[1] + x[2]) / 3);
      q.second = (l3 * l3) / (h * h);
      if (q.size() > 1) {
        q.first = 1;
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      double e[3];
      for (int i = 0; i < 3; ++i)
        e[i] = (p[i] - p[(i + 1) % 3]).squaredNorm();
      std::sort(e, e + 3);
      const Eigen::Vector2d u = p[1] - p[0], v = p[2] - p[0];
      const double area2 = u.x() * v.y() - u.y() * v.x();
      q.first = area2 * area2 / (e[2] * e[1]);
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

  private:
    const FaceChart3D* chart_;
    const SizeField3D* size_;
  };

  SurfaceCriteria(const FaceChart3D& chart, const SizeField3D& size)
      : Base(shape_bound), chart_(&chart), size_(&size) {}
  Is_bad is_bad_object() const { return Is_bad(*chart_, *size_); }

private:
  const FaceChart3D* chart_;
  const SizeField3D* size_;
};

using Mesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, SurfaceCriteria>;

void mesh_face(const GridDecomposition3D& dec, int face_id, const SizeField3D& size,
               CurveCache& curves, SurfaceMesh3D& out) {
  const GridFace3D& face = dec.faces[face_id];
  const FaceChart3D chart(dec.frames[face.frame], face);
  const std::vector<int> loop = face_loop(dec, face, curves);
  if (loop.size() < 3)
    throw MeshError("", "", "internal: degenerate interface face");
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> vh;
  for (int id : loop) {
    const Eigen::Vector2d uv = chart.to_2d(out.points[id]);
    vh.push_back(cdt.insert(Point2(uv.x(), uv.y())));
    vh.back()->info().id = id;
  }
  if (cdt.number_of_vertices() != loop.size())
    throw MeshError("", "", "internal: boundary points of a face coincide in its chart");
  for (std::size_t i = 0; i < vh.size(); ++i)
    cdt.insert_constraint(vh[i], vh[(i + 1) % vh.size()]);
  Mesher mesher(cdt, SurfaceCriteria(chart, size));
  // CGAL 5.5's Delaunay_mesher_no_edge_refinement_2 leaves its seeds_mark flag uninitialized
  // and refine_mesh() reads it (UBSan: "load of value 174 ... for type 'bool'"); with no seeds
  // it does not change the result, but the read is undefined. clear_seeds() sets it.
  mesher.clear_seeds();
  mesher.refine_mesh();
  // Re-mark the domain: only faces inside the boundary loop are output.
  Mesher::mark_facets(cdt, std::vector<Point2>().begin(), std::vector<Point2>().end());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info().id < 0) {
      v->info().id = static_cast<int>(out.points.size());
      out.points.push_back(chart.to_3d({v->point().x(), v->point().y()}));
    }
  std::size_t n_constrained = 0;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    n_constrained += cdt.is_constrained(*e);
  if (n_constrained != loop.size())
    throw MeshError("", "", "internal: a face boundary was split while meshing the face");
  for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
    if (!fh->is_in_domain())
      continue;
    out.triangles.push_back(
        {fh->vertex(0)->info().id, fh->vertex(1)->info().id, fh->vertex(2)->info().id});
    out.triangle_face.push_back(face_id);
  }
}

} // namespace

SurfaceMesh3D mesh_surfaces_3d(const GridDecomposition3D& dec, const SizeField3D& size,
                               double merge_tol) {
  SurfaceMesh3D out;
  PointPool pool(out.points, merge_tol);
  CurveCache curves(dec, size, pool);
  // All curve points first (pooled), then face interiors (never shared).
  for (const GridFace3D& face : dec.faces)
    face_loop(dec, face, curves);
  for (std::size_t i = 0; i < dec.faces.size(); ++i)
    mesh_face(dec, static_cast<int>(i), size, curves, out);
  return out;
}

} // namespace magfem
