#include "mesh/surface_mesher3d.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <unordered_map>
#include <utility>

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

// Divides the curve at(t), t in [lo, hi], so that consecutive points are about h apart:
// integrates 1/h along it and places points at equal increments of the integral. Returns the
// pooled point ids from at(lo) to at(hi); a curve of no length is one point.
template <class Curve>
std::vector<int> divide_curve(const Curve& at, double lo, double hi, const SizeField3D& size,
                              PointPool& pool) {
  const Vec3 a = at(lo), b = at(hi), m = at(0.5 * (lo + hi));
  if ((a - b).norm() + (a - m).norm() < 1e-12 * (1 + a.norm()))
    return {pool.insert(a)};
  std::vector<double> ts{lo}, integral{0};
  double t = lo;
  Vec3 x = a;
  const double dt_probe = 1e-7 * (hi - lo);
  while (t < hi) {
    const double h = size(x);
    const double speed =
        (at(std::min(t + dt_probe, hi)) - at(std::min(t + dt_probe, hi) - dt_probe)).norm() /
        dt_probe;
    const double dt = std::min(hi - t, curve_step * h / std::max(speed, 1e-300));
    const double t_next = t + dt;
    const Vec3 x_next = at(t_next);
    const double h_next = size(x_next);
    integral.push_back(integral.back() + (x_next - x).norm() * 0.5 * (1 / h + 1 / h_next));
    ts.push_back(t_next);
    t = t_next;
    x = x_next;
  }
  const int n_seg = std::max(1, static_cast<int>(std::ceil(integral.back() - 1e-6)));
  std::vector<int> ids{pool.insert(a)};
  std::size_t k_s = 0;
  for (int k = 1; k < n_seg; ++k) {
    const double target = integral.back() * k / n_seg;
    while (integral[k_s + 1] < target)
      ++k_s;
    const double w = (target - integral[k_s]) / (integral[k_s + 1] - integral[k_s]);
    ids.push_back(pool.insert(at(ts[k_s] + w * (ts[k_s + 1] - ts[k_s]))));
  }
  ids.push_back(pool.insert(b));
  return ids;
}

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
  std::vector<int> divide(const EdgeKey& key) const {
    const GridFrame3D& f = dec_.frames[key.frame];
    Vec3 q;
    int n = 0;
    for (int a = 0; a < 3; ++a)
      if (a != key.axis)
        q[a] = f.breaks[a][key.fixed[n++]];
    auto at = [&](double t) {
      Vec3 qq = q;
      qq[key.axis] = t;
      return f.point(qq);
    };
    return divide_curve(at, f.lo(key.axis, key.cell), f.hi(key.axis, key.cell), size_, pool_);
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

// Chart coordinates -> the 3D point on the surface.
using ToSurface = std::function<Vec3(const Eigen::Vector2d&)>;

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
    Is_bad(const ToSurface& chart, const SizeField3D& size)
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
        x[i] = (*chart_)(p[i]);
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
    const ToSurface* chart_;
    const SizeField3D* size_;
  };

  SurfaceCriteria(const ToSurface& chart, const SizeField3D& size)
      : Base(shape_bound), chart_(&chart), size_(&size) {}
  Is_bad is_bad_object() const { return Is_bad(*chart_, *size_); }

private:
  const ToSurface* chart_;
  const SizeField3D* size_;
};

using Mesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, SurfaceCriteria>;

// Refines the constrained triangulation to the size field (constrained edges are never split:
// they are shared with neighbouring faces) and appends its points and its triangles inside
// the constraints (tagged `face_code`) to `out`. Returns the number of constrained edges.
std::size_t refine_into(Cdt& cdt, const ToSurface& to_3d, const SizeField3D& size, int face_code,
                        SurfaceMesh3D& out) {
  Mesher mesher(cdt, SurfaceCriteria(to_3d, size));
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
      out.points.push_back(to_3d({v->point().x(), v->point().y()}));
    }
  std::size_t n_constrained = 0;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    n_constrained += cdt.is_constrained(*e);
  for (auto fh = cdt.finite_faces_begin(); fh != cdt.finite_faces_end(); ++fh) {
    if (!fh->is_in_domain())
      continue;
    out.triangles.push_back(
        {fh->vertex(0)->info().id, fh->vertex(1)->info().id, fh->vertex(2)->info().id});
    out.triangle_face.push_back(face_code);
  }
  return n_constrained;
}

// Triangulates the closed loop of surface points (ids into out.points) in its chart by 2D
// Delaunay refinement without splitting the loop's segments; the triangles go to `out` with
// `face_code` as their triangle_face.
template <class Chart>
void mesh_loop(const Chart& chart, const std::vector<int>& loop, const SizeField3D& size,
               int face_code, SurfaceMesh3D& out) {
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
  const ToSurface to_3d = [&chart](const Eigen::Vector2d& uv) { return chart.to_3d(uv); };
  if (refine_into(cdt, to_3d, size, face_code, out) != loop.size())
    throw MeshError("", "", "internal: a face boundary was split while meshing the face");
}

void mesh_face(const GridDecomposition3D& dec, int face_id, const SizeField3D& size,
               CurveCache& curves, SurfaceMesh3D& out) {
  const GridFace3D& face = dec.faces[face_id];
  mesh_loop(FaceChart3D(dec.frames[face.frame], face), face_loop(dec, face, curves), size, face_id,
            out);
}

// The plane of one triangle of a TriangleSurface, with isometric coordinates.
class TriangleChart {
public:
  TriangleChart(const Vec3& a, const Vec3& b, const Vec3& c) : origin_(a) {
    e1_ = (b - a).normalized();
    e2_ = (b - a).cross(c - a).cross(b - a).normalized();
  }
  Eigen::Vector2d to_2d(const Vec3& x) const {
    return {(x - origin_).dot(e1_), (x - origin_).dot(e2_)};
  }
  Vec3 to_3d(const Eigen::Vector2d& uv) const { return origin_ + uv.x() * e1_ + uv.y() * e2_; }

private:
  Vec3 origin_, e1_, e2_;
};

// The triangles of the TriangleSurface parts: each edge divided once by the size field (so
// neighbours conform), each triangle refined in its plane. The input corners stay where they
// are and every new point lies on an input triangle: the surface is split, never moved.
void mesh_surface_parts(const Geometry3D& geo, const SizeField3D& size, PointPool& pool,
                        SurfaceMesh3D& out) {
  for (std::size_t p = 0; p < geo.parts.size(); ++p) {
    const auto* surface = std::get_if<TriangleSurface>(&geo.parts[p].shape);
    if (!surface)
      continue;
    std::vector<Vec3> x;
    for (const Vec3& local : surface->points)
      x.push_back(geo.parts[p].placement.to_global(local));
    std::map<std::pair<int, int>, std::vector<int>> edges; // from the lower to the higher id
    auto edge = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      auto it = edges.find(key);
      if (it == edges.end()) {
        const Vec3 a = x[key.first], b = x[key.second];
        it = edges
                 .emplace(key, divide_curve([&](double t) { return Vec3(a + t * (b - a)); }, 0.0,
                                            1.0, size, pool))
                 .first;
      }
      return it->second;
    };
    for (const auto& t : surface->triangles)
      for (int k = 0; k < 3; ++k)
        edge(t[k], t[(k + 1) % 3]);
    const int tag = part_surface_tag(static_cast<int>(p));
    for (const auto& t : surface->triangles) {
      std::vector<int> loop;
      for (int k = 0; k < 3; ++k) {
        std::vector<int> ids = edge(t[k], t[(k + 1) % 3]);
        if (t[k] > t[(k + 1) % 3])
          std::reverse(ids.begin(), ids.end());
        loop.insert(loop.end(), ids.begin(), ids.end() - 1);
      }
      mesh_loop(TriangleChart(x[t[0]], x[t[1]], x[t[2]]), loop, size, tag, out);
    }
  }
}

using Edge = std::pair<int, int>; // point ids, lower first

Edge edge_of(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

// The line where planes p and q meet (the third axis c), within the ball and on the kept side
// of a third plane normal to it: its points on kept faces, its ends, and points between them
// at the local size. Its segments are constraints of both planes' facets.
void add_plane_line(const std::vector<SymmetryPlane3D>& planes, std::size_t p, std::size_t q,
                    double radius, double tol, const SizeField3D& size, PointPool& pool,
                    std::vector<Vec3>& points, std::vector<std::set<Edge>>& edges) {
  const int c = 3 - planes[p].axis - planes[q].axis;
  double lo = -radius;
  for (const SymmetryPlane3D& r : planes)
    if (r.axis == c)
      lo = 0;
  const double hi = radius;
  auto at = [c](double t) {
    Vec3 x = Vec3::Zero();
    x[c] = t;
    return x;
  };
  pool.insert(at(lo));
  pool.insert(at(hi));
  std::vector<std::pair<double, int>> on_line;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::abs(points[i][planes[p].axis]) <= tol && std::abs(points[i][planes[q].axis]) <= tol)
      on_line.emplace_back(points[i][c], static_cast<int>(i));
  std::sort(on_line.begin(), on_line.end());
  for (std::size_t k = 0; k + 1 < on_line.size(); ++k) {
    const std::vector<int> ids =
        divide_curve(at, on_line[k].first, on_line[k + 1].first, size, pool);
    for (std::size_t i = 0; i + 1 < ids.size(); ++i)
      for (std::size_t plane : {p, q})
        edges[plane].insert(edge_of(ids[i], ids[i + 1]));
  }
}

// Triangulates the plane's share: every surface point on it is a vertex, every edge in
// `edges` a constraint (the loops of the kept faces that end on the plane close the share).
void mesh_plane(const SymmetryPlane3D& plane, int index, const std::set<Edge>& edges,
                const SizeField3D& size, SurfaceMesh3D& out) {
  const int u = (plane.axis + 1) % 3, v = (plane.axis + 2) % 3;
  Cdt cdt;
  std::unordered_map<int, Cdt::Vertex_handle> vh;
  for (std::size_t i = 0; i < out.points.size(); ++i)
    if (out.points[i][plane.axis] == 0) { // snapped (mesh_surfaces_3d)
      auto h = cdt.insert(Point2(out.points[i][u], out.points[i][v]));
      h->info().id = static_cast<int>(i);
      vh[static_cast<int>(i)] = h;
    }
  for (const Edge& e : edges)
    cdt.insert_constraint(vh.at(e.first), vh.at(e.second));
  const ToSurface to_3d = [&](const Eigen::Vector2d& uv) {
    Vec3 x = Vec3::Zero();
    x[u] = uv.x();
    x[v] = uv.y();
    return x;
  };
  if (refine_into(cdt, to_3d, size, symmetry_face_code(index), out) != edges.size())
    throw MeshError("", "",
                    std::string("internal: the curves on the symmetry plane ") +
                        axis_name(plane.axis) + " = 0 cross each other");
}

} // namespace

SurfaceMesh3D mesh_surfaces_3d(const Geometry3D& geo, const GridDecomposition3D& dec,
                               const SizeField3D& size, double merge_tol,
                               const std::vector<SymmetryPlane3D>& planes, double outer_radius) {
  SurfaceMesh3D out;
  PointPool pool(out.points, merge_tol);
  CurveCache curves(dec, size, pool);
  // All curve points first (pooled), then face interiors (never shared).
  const double tol = merge_tol;
  std::vector<std::set<Edge>> plane_edges(planes.size());
  auto on_plane = [&](int id, const SymmetryPlane3D& p) {
    return std::abs(out.points[id][p.axis]) <= tol;
  };
  for (const GridFace3D& face : dec.faces) {
    const std::vector<int> loop = face_loop(dec, face, curves);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      for (std::size_t p = 0; p < planes.size(); ++p)
        if (a != b && on_plane(a, planes[p]) && on_plane(b, planes[p]))
          plane_edges[p].insert(edge_of(a, b));
    }
  }
  for (std::size_t p = 0; p < planes.size(); ++p)
    for (std::size_t q = p + 1; q < planes.size(); ++q)
      add_plane_line(planes, p, q, outer_radius, tol, size, pool, out.points, plane_edges);
  // Points on a plane lie on it exactly: its facets are then coplanar for TetGen.
  for (Vec3& x : out.points)
    for (const SymmetryPlane3D& p : planes)
      if (std::abs(x[p.axis]) <= tol)
        x[p.axis] = 0;
  for (std::size_t i = 0; i < dec.faces.size(); ++i)
    mesh_face(dec, static_cast<int>(i), size, curves, out);
  mesh_surface_parts(geo, size, pool, out);
  // A face triangle lying in a plane would double its facet (a face curved onto the plane).
  for (std::size_t t = 0; t < out.triangles.size(); ++t)
    for (const SymmetryPlane3D& p : planes)
      if (out.points[out.triangles[t][0]][p.axis] == 0 &&
          out.points[out.triangles[t][1]][p.axis] == 0 &&
          out.points[out.triangles[t][2]][p.axis] == 0)
        throw MeshError("", "",
                        std::string("internal: a surface triangle lies in the symmetry plane ") +
                            axis_name(p.axis) + " = 0");
  for (std::size_t p = 0; p < planes.size(); ++p)
    mesh_plane(planes[p], static_cast<int>(p), plane_edges[p], size, out);
  return out;
}

} // namespace magfem
