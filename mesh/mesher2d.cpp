// The only translation unit that sees CGAL. Meshing runs in two passes:
//  1. coarse pass: outlines at their own sizes are inserted as constraints, the faces are
//     classified, and the interfaces between regions (and the air gaps between them) become the
//     sources of a graded size field;
//  2. final pass: outlines are re-cut to that field, constraints hidden inside later parts are
//     dropped, and CGAL's Delaunay refinement runs with the field as its size criterion.
#include "mesh/mesher2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "core/constants.hpp"
#include "mesh/constraint_set2d.hpp"
#include "mesh/gap_rule2d.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesh_finish2d.hpp"
#include "mesh/region_map2d.hpp"
#include "mesh/region_overlap2d.hpp"
#include "mesh/size_field2d.hpp"

namespace magfem {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>; // info: region of the face
using Cfb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K, Cfb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: constraints of overlapping parts may cross; CGAL inserts the crossings.
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Point = CDT::Point;
using FaceHandle = CDT::Face_handle;
using VertexHandle = CDT::Vertex_handle;

constexpr int frame_vertex = -2;           // vertex info of the frame corners
constexpr double grading = 0.5;            // size-field slope (see size_field2d.hpp)
constexpr double max_min_angle_deg = 30.0; // cap of the quality bound (terminates in practice)
// CGAL is asked for this much more than the promised bound: moving the vertices it adds on an
// outer chord onto the circle (by up to the sagitta) tilts the triangles there slightly.
constexpr double angle_margin_deg = 1.0;
constexpr double min_gap_tolerances = 3.0; // narrower gaps count as contact (gap_rule2d.hpp)
constexpr std::size_t max_vertices = 5'000'000;
constexpr int steps_between_checks = 4096;

Vec2 to_vec(const Point& p) {
  return {p.x(), p.y()};
}
Point to_point(const Vec2& v) {
  return {v.x(), v.y()};
}

Vec2 centroid(const FaceHandle& f) {
  return (to_vec(f->vertex(0)->point()) + to_vec(f->vertex(1)->point()) +
          to_vec(f->vertex(2)->point())) /
         3.0;
}

// Delaunay_mesh_size_criteria_2 with the size bound taken from a size field at the centroid.
class FieldCriteria : public CGAL::Delaunay_mesh_size_criteria_2<CDT> {
  using AngleBase = CGAL::Delaunay_mesh_criteria_2<CDT>;
  using SizeBase = CGAL::Delaunay_mesh_size_criteria_2<CDT>;

public:
  using Quality = SizeBase::Quality;

  FieldCriteria(double aspect_bound, const SizeField2D& field)
      : AngleBase(aspect_bound), SizeBase(aspect_bound, 0), field_(&field) {}

  class Is_bad : public SizeBase::Is_bad {
  public:
    Is_bad(double aspect_bound, const SizeField2D* field, const K& traits)
        : SizeBase::Is_bad(aspect_bound, 0, traits), field_(field) {}

    CGAL::Mesh_2::Face_badness operator()(const Quality q) const {
      return SizeBase::Is_bad::operator()(q);
    }

    CGAL::Mesh_2::Face_badness operator()(const FaceHandle& fh, Quality& q) const {
      const Vec2 a = to_vec(fh->vertex(0)->point()), b = to_vec(fh->vertex(1)->point()),
                 c = to_vec(fh->vertex(2)->point());
      std::array<double, 3> l2{(b - c).squaredNorm(), (c - a).squaredNorm(), (a - b).squaredNorm()};
      std::sort(l2.begin(), l2.end());
      const double h = (*field_)((a + b + c) / 3.0);
      q.second = l2[2] / (h * h);
      if (q.second > 1) {
        q.first = 1; // the sine is not needed: too big is imperative
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      const double twice_area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      q.first = twice_area * twice_area / (l2[2] * l2[1]); // squared sine of the smallest angle
      return q.first < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

  private:
    const SizeField2D* field_;
  };

  Is_bad is_bad_object() const { return Is_bad(bound(), field_, traits); }

private:
  const SizeField2D* field_;
};

// Vertices of different outlines closer than this are one vertex (see constraint_set2d.hpp):
// a hundredth of the smallest size the field can ask for.
double merge_distance(const Geometry2D& g) {
  const MeshOptions2D& o = g.options;
  return 0.01 * std::min(1.0, o.size_scale) * o.chord_tolerance / o.gap_layers;
}

void insert_outlines(CDT& cdt, const RegionMap2D& map, const Geometry2D& g) {
  const double merge = merge_distance(g);
  const bool axi = g.symmetry == Symmetry2D::axisymmetric;
  // A square frame around the outermost circle keeps that circle off the convex hull: a point
  // CGAL puts on a hull edge by rounding lands just outside it and leaves a flat triangle.
  const Outline2D& outer = map.shell() ? *map.shell() : map.domain();
  const double frame = 1.5 * outer.box_max().cwiseAbs().maxCoeff();
  for (const Vec2& corner :
       {Vec2(-frame, -frame), Vec2(frame, -frame), Vec2(frame, frame), Vec2(-frame, frame)})
    cdt.insert(to_point(corner))->info() = frame_vertex;
  std::vector<std::vector<Vec2>> loops = map.domain().loops();
  if (map.shell())
    loops.push_back(map.shell()->loops().front());
  // Parts are cut at the symmetry planes: nothing beyond them is inserted (their faces would
  // be outside the domain, but refined all the same).
  for (std::size_t i = 0; i < map.n_parts(); ++i)
    for (const auto& loop : map.part(i).loops())
      if (auto cut = clip_to_share(loop, g.planes); !cut.empty())
        loops.push_back(std::move(cut));
  ConstraintSet2D set = build_constraint_set(loops, merge);
  // Arc ends on the axis (or a symmetry plane) come out of cos(pi/2) a hair off it; exactly on
  // it, CGAL splits the axis side there instead of leaving a sliver beside it.
  for (Vec2& p : set.points) {
    if (axi && std::abs(p.x()) < merge)
      p.x() = 0;
    for (const SymmetryPlane2D& plane : g.planes)
      if (std::abs(p[plane.axis]) < merge)
        p[plane.axis] = 0;
  }
  std::vector<VertexHandle> vs;
  FaceHandle hint;
  for (const Vec2& p : set.points) {
    vs.push_back(cdt.insert(to_point(p), hint));
    vs.back()->info() = 0;
    hint = vs.back()->face();
  }
  for (const auto& s : set.segments)
    if (vs[s[0]] != vs[s[1]])
      cdt.insert_constraint(vs[s[0]], vs[s[1]]);
}

// Faces separated by no constraint share a region. Each such component is classified once, at
// the centroid of its largest face: a sliver left by rounding next to a constraint could have
// its centroid on the wrong side, a large face cannot.
void classify(CDT& cdt, const RegionMap2D& map) {
  constexpr int unvisited = std::numeric_limits<int>::min();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    f->info() = unvisited;
  std::vector<FaceHandle> component, stack;
  for (auto seed = cdt.finite_faces_begin(); seed != cdt.finite_faces_end(); ++seed) {
    if (seed->info() != unvisited)
      continue;
    component.clear();
    stack.assign(1, seed);
    seed->info() = 0;
    FaceHandle largest = seed;
    double largest_area = -1;
    while (!stack.empty()) {
      const FaceHandle f = stack.back();
      stack.pop_back();
      component.push_back(f);
      const double area =
          std::abs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
      if (area > largest_area)
        largest_area = area, largest = f;
      for (int i = 0; i < 3; ++i) {
        const FaceHandle n = f->neighbor(i);
        if (f->is_constrained(i) || cdt.is_infinite(n) || n->info() != unvisited)
          continue;
        n->info() = 0;
        stack.push_back(n);
      }
    }
    const int r = map.region_of(centroid(largest));
    for (const FaceHandle& f : component)
      f->info() = r;
  }
}

int region(const CDT& cdt, const FaceHandle& f) {
  return cdt.is_infinite(f) ? region_outside : f->info();
}

// Size sources on every interface (the finer side's size) and the air boundaries for the gap
// rule, from a classified triangulation.
void collect_interfaces(const CDT& cdt, const RegionMap2D& map, std::vector<SizeSource2D>& sources,
                        std::vector<AirBoundary2D>& air) {
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if (!cdt.is_constrained(*e))
      continue;
    const FaceHandle f = e->first;
    const int i = e->second;
    const int r1 = region(cdt, f), r2 = region(cdt, f->neighbor(i));
    if (r1 == r2)
      continue;
    // f lies on the left of a -> b.
    const Vec2 a = to_vec(f->vertex(CDT::ccw(i))->point());
    const Vec2 b = to_vec(f->vertex(CDT::cw(i))->point());
    sources.push_back({a, b, std::min(map.size_of(r1), map.size_of(r2))});
    if (r1 != region_background && r2 != region_background)
      continue;
    const int other = r1 == region_background ? r2 : r1;
    const Vec2 t = (b - a).normalized();
    const Vec2 left(-t.y(), t.x());
    air.push_back({a, b, r1 == region_background ? left : Vec2(-left),
                   other >= 0 ? other : owner_domain_boundary});
  }
}

// Pass 1: the size field from interfaces and gaps of the outlines at their own sizes.
SizeField2D build_size_field(const Geometry2D& g, const RegionMap2D& coarse) {
  CDT cdt;
  insert_outlines(cdt, coarse, g);
  classify(cdt, coarse);
  std::vector<SizeSource2D> sources;
  std::vector<AirBoundary2D> air;
  collect_interfaces(cdt, coarse, sources, air);
  const MeshOptions2D& o = g.options;
  const GapRuleOptions gap{o.gap_layers, o.size_scale, coarse.size_of(region_background), grading,
                           min_gap_tolerances * o.chord_tolerance};
  const auto gaps = gap_sources(air, gap);
  sources.insert(sources.end(), gaps.begin(), gaps.end());
  const double floor = std::min(1.0, o.size_scale) * o.chord_tolerance / o.gap_layers;
  const double r =
      g.outer.kind == OuterKind::open ? g.outer.shell_ratio * g.outer.radius : g.outer.radius;
  return SizeField2D([&coarse](const Vec2& x) { return coarse.size_of(coarse.region_of(x)); },
                     std::move(sources), grading, floor, Vec2(-r, -r), Vec2(r, r));
}

// Constraints between faces of one region are edges of parts hidden under later parts: drop
// them, and the vertices left without constraints, so they do not shape the mesh.
void drop_hidden_constraints(CDT& cdt) {
  std::vector<std::pair<VertexHandle, VertexHandle>> hidden;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    const FaceHandle f = e->first;
    const FaceHandle n = f->neighbor(e->second);
    if (cdt.is_constrained(*e) && !cdt.is_infinite(n) && f->info() == n->info())
      hidden.emplace_back(f->vertex(CDT::ccw(e->second)), f->vertex(CDT::cw(e->second)));
  }
  for (const auto& [va, vb] : hidden) {
    FaceHandle f;
    int i = 0;
    if (cdt.is_edge(va, vb, f, i))
      cdt.remove_constrained_edge(f, i);
  }
  std::vector<VertexHandle> loose;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info() != frame_vertex && !cdt.are_there_incident_constraints(v))
      loose.push_back(v);
  for (const VertexHandle& v : loose)
    cdt.remove(v);
}

void refine(CDT& cdt, const Geometry2D& g, const SizeField2D& field) {
  const double angle =
      (std::min(g.options.min_angle_deg, max_min_angle_deg) + angle_margin_deg) * deg_to_rad;
  const FieldCriteria criteria(std::sin(angle) * std::sin(angle), field);
  CGAL::Delaunay_mesher_2<CDT, FieldCriteria> mesher(cdt, criteria);
  mesher.init();
  for (long step = 1; !mesher.is_refinement_done(); ++step) {
    mesher.step_by_step_refine_mesh();
    if (step % steps_between_checks == 0 && cdt.number_of_vertices() > max_vertices)
      throw MeshError("", "",
                      "the mesh exceeds " + std::to_string(max_vertices) +
                          " vertices: sizes, chord tolerance or gaps are too small");
  }
}

// Moves the vertices of the outermost boundary (and of the shell's inner circle) exactly onto
// their circle: CGAL puts the vertices it adds on a chord on the chord (up to the sagitta
// inside); moving them outwards cannot invert the triangles inside.
void snap_to_circle(Mesh2D& mesh, const std::vector<std::array<int, 2>>& edges, double r) {
  for (const auto& e : edges)
    for (int v : e)
      mesh.nodes[v] *= r / mesh.nodes[v].norm();
}

// The boundary edges on the axis (both ends at x = 0 exactly, see insert_outlines) move from
// outer_edges to axis_edges.
void split_off_axis(Mesh2D& mesh) {
  std::vector<std::array<int, 2>> outer;
  for (const auto& e : mesh.outer_edges)
    (mesh.nodes[e[0]].x() == 0 && mesh.nodes[e[1]].x() == 0 ? mesh.axis_edges : outer).push_back(e);
  mesh.outer_edges = std::move(outer);
}

// The boundary edges on a symmetry plane (both ends exactly on it, see insert_outlines) move
// from outer_edges to symmetry_edges.
void split_off_planes(Mesh2D& mesh, const Geometry2D& g) {
  mesh.symmetry = g.planes;
  mesh.symmetry_edges.assign(g.planes.size(), {});
  std::vector<std::array<int, 2>> outer;
  for (const auto& e : mesh.outer_edges) {
    std::size_t k = 0;
    while (k < g.planes.size() &&
           !(mesh.nodes[e[0]][g.planes[k].axis] == 0 && mesh.nodes[e[1]][g.planes[k].axis] == 0))
      ++k;
    (k < g.planes.size() ? mesh.symmetry_edges[k] : outer).push_back(e);
  }
  mesh.outer_edges = std::move(outer);
}

Mesh2D export_mesh(CDT& cdt, const Geometry2D& g, const RegionMap2D& map) {
  Mesh2D mesh;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    v->info() = -1;
  const auto index = [&](const VertexHandle& v) {
    if (v->info() < 0) {
      v->info() = int(mesh.nodes.size());
      mesh.nodes.push_back(to_vec(v->point()));
    }
    return v->info();
  };
  // Kept faces get their triangle index as info (regions move to triangle_part), so that the
  // adjacency comes straight from CGAL.
  std::vector<FaceHandle> faces;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() == region_outside) {
      f->info() = -1;
      continue;
    }
    mesh.triangles.push_back({index(f->vertex(0)), index(f->vertex(1)), index(f->vertex(2))});
    mesh.triangle_part.push_back(f->info());
    f->info() = int(faces.size());
    faces.push_back(f);
  }
  Neighbours2D nb(faces.size());
  for (std::size_t t = 0; t < faces.size(); ++t)
    for (int k = 0; k < 3; ++k) { // edge k runs from vertex k to k + 1, opposite vertex k + 2
      const FaceHandle n = faces[t]->neighbor((k + 2) % 3);
      nb[t][k] = cdt.is_infinite(n) ? -1 : n->info();
    }
  remove_slivers(mesh, nb);
  mesh.outer_edges = boundary_edges(mesh, nb);
  if (g.symmetry == Symmetry2D::axisymmetric)
    split_off_axis(mesh);
  split_off_planes(mesh, g);
  const double r1 = g.outer.radius;
  if (g.outer.kind == OuterKind::open) {
    mesh.shell_inner_radius = r1;
    mesh.shell_outer_radius = g.outer.shell_ratio * r1;
    snap_to_circle(mesh, mesh.outer_edges, mesh.shell_outer_radius);
    snap_to_circle(mesh, interface_edges(mesh, nb, region_shell), r1);
  } else {
    snap_to_circle(mesh, mesh.outer_edges, r1);
  }
  mesh.quality = measure_quality(mesh);
  mesh.quality.max_sagitta = map.max_sagitta();
  return mesh;
}

void check_mesh(const Mesh2D& mesh, const Geometry2D& g, const RegionMap2D& map) {
  if (mesh.triangles.empty() || !(mesh.quality.min_area > 0))
    throw MeshError("", "", "CGAL produced a degenerate or inverted triangle");
  std::vector<char> used(g.parts.size(), 0);
  for (int r : mesh.triangle_part)
    if (r >= 0)
      used[std::size_t(r)] = 1;
  // A part wholly beyond a symmetry plane is the mirror image of a meshed one.
  const auto beyond_planes = [&](std::size_t i) {
    return !g.planes.empty() && clip_to_share(map.part(i).loops().front(), g.planes).empty();
  };
  for (std::size_t i = 0; i < used.size(); ++i)
    if (!used[i] && !beyond_planes(i))
      // Either later parts cover it, or it is thinner than the chord tolerance lets the
      // mesher see (a 10 nm ring at 10 um: its two circles become one outline).
      throw MeshError(g.parts[i].name, "",
                      "the part has no element: later parts cover it completely, or it is "
                      "thinner than the mesh can resolve (about the chord tolerance)");
}

} // namespace

Mesh2D build_mesh_2d(const Geometry2D& g, const SizeField2D* refine_sizes) {
  // Pass 1 cuts every outline to its own region's size.
  const RegionMap2D coarse(g, [&g](int region, const Vec2&) {
    const MeshOptions2D& o = g.options;
    const double own = region >= 0 && g.parts[std::size_t(region)].max_size > 0
                           ? g.parts[std::size_t(region)].max_size
                           : o.default_size;
    return own * o.size_scale;
  });
  check_region_overlaps2d(g, coarse); // before any triangle is made
  const SizeField2D field = build_size_field(g, coarse);
  // Pass 2 re-cuts them to the graded field, which sees both sides of every boundary.
  const RegionMap2D map(
      g, [&](int region, const Vec2& x) { return std::min(field(x), coarse.size_of(region)); },
      coarse.shell_size());
  try {
    CDT cdt;
    insert_outlines(cdt, map, g);
    classify(cdt, map);
    drop_hidden_constraints(cdt);
    refine(cdt, g, refine_sizes ? *refine_sizes : field);
    classify(cdt, map);
    Mesh2D mesh = export_mesh(cdt, g, map);
    check_mesh(mesh, g, map);
    return mesh;
  } catch (const MeshError&) {
    throw;
  } catch (const std::exception& e) {
    throw MeshError("", "", std::string("CGAL could not build the mesh: ") + e.what());
  }
}

} // namespace magfem
