// The only translation unit that includes tetgen.h (TetGen is AGPL-3.0: keep it fenced here).
#include "mesh/mesher3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include <tetgen.h>

#include "core/constants.hpp"
#include "core/parallel_blocks.hpp"
#include "core/thread_count.hpp"
#include "mesh/domain_split3d.hpp"
#include "mesh/face_chart3d.hpp"
#include "mesh/face_soup3d.hpp"
#include "mesh/grid_frame3d.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/mesh_quality3d.hpp"
#include "mesh/size_field3d.hpp"
#include "mesh/spatial_order3d.hpp"
#include "mesh/surface_mesher3d.hpp"
#include "mesh/surface_part_checks3d.hpp"
#include "mesh/surface_part_rays3d.hpp"
#include "mesh/tetgen_shared_state.hpp"
#include "mesh/tetgen_termination.hpp"
#include "mesh/unresolved_gaps3d.hpp"

namespace magfem {
// mesh/tetgen_termination.cpp: TetGen errors reach our catch instead of aborting.
extern const int tetgen_termination_interposed;

namespace {

constexpr double grading = 0.3;         // size growth per unit distance from a feature
constexpr double sample_fraction = 0.5; // source spacing as a fraction of the local size
// Field sources carry slightly smaller sizes than required so that the field between sources
// (which grows by grading * distance) still meets the requirement.
constexpr double chord_margin = 0.9;
// Gap sources: spacing w/L along and across the gap, so any point of the gap is within
// 0.87 w/L of a source; (h_s + grading * 0.87 w/L) / (1 - slack) <= w/L needs
// h_s <= (0.95 - 0.26) w/L.
constexpr double gap_source_factor = 1 - size_field_slack - grading * 0.87;
constexpr double min_dihedral_request_deg = 10; // TetGen -q second argument
// The coarse triangles for intersection tests and gap rays divide a face into at most about
// this many steps per direction (their chord error is far below any gap worth resolving).
constexpr double soup_divisions = 16;

// Region and chord size rules (all in metres, already multiplied by size_scale).
struct SizeRules {
  const Geometry3D& geo;
  double default_size = 0;
  double scale = 1;
  double tol = 0;

  explicit SizeRules(const Geometry3D& g) : geo(g) {
    const MeshOptions3D& o = g.options;
    scale = o.size_scale > 0 ? o.size_scale : 1.0;
    default_size = (o.default_size > 0 ? o.default_size : g.outer.radius / 8);
    tol = o.chord_tolerance;
  }
  double region(int label) const {
    if (label == region_exterior_3d)
      return std::numeric_limits<double>::infinity();
    if (label >= 0 && geo.parts[label].max_size > 0)
      return scale * geo.parts[label].max_size;
    if (label == region_shell_3d && geo.options.shell_size > 0)
      return scale * geo.options.shell_size;
    return scale * default_size;
  }
  // Sagitta of a triangle of edge h on a surface of curvature radius R is about h^2 / (6 R).
  // A coarser --mesh-scale keeps the chord limit of surfaces whose facets stay flat (their
  // geometry would coarsen with the mesh) and lets that of spheres grow with it when the
  // solver curves the elements onto them (order 2, MeshOptions3D::spheres_curved). Without
  // that the spherical actuator meshed to about a million tetrahedra at every scale above 1.5.
  double chord(double radius, bool curved_by_solver) const {
    if (tol <= 0 || !std::isfinite(radius))
      return std::numeric_limits<double>::infinity();
    return chord_margin * std::sqrt(6 * radius * tol) *
           (curved_by_solver ? scale : std::min(scale, 1.0));
  }
  double face(const GridFace3D& f) const {
    return std::min(region(f.label_low), region(f.label_high));
  }
  // The chord tolerance is a property of the parts' surfaces; the outer spheres only need
  // their nodes on the sphere, which they have exactly.
  double face_chord(const GridFace3D& f, const FaceChart3D& chart, double radius) const {
    return (f.label_low >= 0 || f.label_high >= 0)
               ? chord(radius, geo.options.spheres_curved && chart.is_sphere())
               : std::numeric_limits<double>::infinity();
  }
};

// Smallest curvature radius a face's chord size uses: cones are clamped at a tenth of their
// largest radius so that the apex does not ask for infinitely small elements.
double curvature_floor(const FaceChart3D& chart, const FaceSamples3D& s) {
  double r_max = 0;
  for (const Vec3& x : s.points) {
    const double r = chart.curvature_radius(x);
    if (std::isfinite(r))
      r_max = std::max(r_max, r);
  }
  return 0.1 * r_max;
}

struct FaceSizing {
  std::vector<double> spacing;      // per face: size-source spacing
  std::vector<double> soup_spacing; // per face: coarse triangles for geometric queries
  std::vector<double> floor;        // curvature floor per face
};

// Sample spacing of each face: a fraction of the smallest intrinsic size on it.
FaceSizing face_sizing(const GridDecomposition3D& dec, const SizeRules& rules) {
  FaceSizing fs;
  for (const GridFace3D& face : dec.faces) {
    const GridFrame3D& fr = dec.frames[face.frame];
    const FaceChart3D chart(fr, face);
    const FaceSamples3D corners = sample_face(fr, face, std::numeric_limits<double>::max());
    const double floor = curvature_floor(chart, corners);
    double h = rules.face(face);
    for (const Vec3& x : corners.points)
      h = std::min(h, rules.face_chord(face, chart, std::max(chart.curvature_radius(x), floor)));
    fs.spacing.push_back(sample_fraction * h);
    fs.floor.push_back(floor);
    double extent = 0;
    for (const Vec3& a : corners.points)
      for (const Vec3& b : corners.points)
        extent = std::max(extent, (a - b).norm());
    fs.soup_spacing.push_back(std::max(fs.spacing.back(), extent / soup_divisions));
  }
  return fs;
}

bool is_air(int label) {
  return label == region_background_3d;
}

// Faces of two parts (or a part and the domain boundary) closer than this fraction of the
// local size are "nearly coincident": TetGen fills the slab between them with flat slivers
// (0.00 deg dihedral, measured on two boxes 1e-5 mm apart) or rejects the input, and the gap
// cannot be meant (a modelling slip: they were meant to touch). Narrow gaps above it are
// resolved by the gap rule (gap_layers).
constexpr double coincident_fraction = 1e-3;

// Throws MeshError naming both parts when the face seen from x (on the part side of an air
// face, looking into the air along n) is nearly coincident with the first face across.
// Planar faces only: the coarse triangles of curved faces lie up to their sagitta (microns)
// off the surface, and near edges a ray meets a neighbour's triangle that close (measured on
// the segment arrays of benchmark32_radial: 2.9 um); planar triangles are exact. The face
// hit must also face the ray (within 25 deg): at a re-entrant edge the neighbouring face is
// met at a glancing angle, not across a slab.
void check_not_coincident(const Geometry3D& geo, const GridDecomposition3D& dec,
                          const FaceSoup3D& soup, const GridFace3D& face, const Vec3& x,
                          const Vec3& n, double eps, double h) {
  const int self = is_air(face.label_low) ? face.label_high : face.label_low;
  if (self < 0)
    return; // the outer sphere
  if (std::isfinite(FaceChart3D(dec.frames[face.frame], face).curvature_radius(x)))
    return;
  int hit = -1;
  const double w = soup.distance_to_face(x + eps * n, n, 0, &hit) + eps;
  if (hit < 0 || !(w < coincident_fraction * h))
    return;
  const GridFace3D& other = dec.faces[hit];
  const GridFrame3D& other_frame = dec.frames[other.frame];
  const Vec3 y = x + w * n;
  if (std::isfinite(FaceChart3D(other_frame, other).curvature_radius(y)) ||
      std::abs(face_normal(other_frame, other, y).dot(n)) < std::cos(25 * pi / 180))
    return;
  const int them = is_air(other.label_low) ? other.label_high : other.label_low;
  char gap[160];
  std::snprintf(gap, sizeof gap, "%.3g m (the mesh size there is %.3g m)", w, h);
  const std::string whom = them >= 0 ? "a face of part '" + geo.parts[them].name + "'"
                                     : std::string("the domain boundary");
  throw MeshError(geo.parts[self].name, "",
                  "a face lies " + std::string(gap) + " from " + whom +
                      ": nearly coincident faces cannot be meshed; make them touch or move them "
                      "at least a thousandth of the mesh size apart");
}

// Whether the part on the solid side of a face (an air face: background on one side) is an
// air part. Such faces bound no gap (see add_surface_sources).
bool is_air_part(const Geometry3D& geo, const GridFace3D& face) {
  const int part = is_air(face.label_low) ? face.label_high : face.label_low;
  return part >= 0 && geo.parts[static_cast<std::size_t>(part)].air;
}

// Adds point sources for every face sample (its intrinsic size) and for narrow air gaps.
// Gaps across which the element size stays above order x the gap width (the element nodes
// farther apart than the gap is wide: a --mesh-scale above order x gap_layers) are recorded in
// `unresolved` when given.
void add_surface_sources(const GridDecomposition3D& dec, const SizeRules& rules,
                         const FaceSizing& fs, const FaceSoup3D& soup, SizeField3D& field,
                         UnresolvedGaps* unresolved) {
  const int layers = std::max(1, rules.geo.options.gap_layers);
  const int order = std::max(1, rules.geo.options.element_order);
  const double eps = 1e-7 * rules.geo.outer.radius;
  for (std::size_t f = 0; f < dec.faces.size(); ++f) {
    const GridFace3D& face = dec.faces[f];
    const GridFrame3D& fr = dec.frames[face.frame];
    const FaceChart3D chart(fr, face);
    auto intrinsic = [&](const Vec3& x) {
      return std::min(
          rules.face(face),
          rules.face_chord(face, chart, std::max(chart.curvature_radius(x), fs.floor[f])));
    };
    for (const Vec3& x : sample_face(fr, face, fs.spacing[f]).points)
      field.add_source(x, intrinsic(x));
    // A gap lies between two parts: the space between a part and the domain boundary is no
    // gap (the field is smooth there, and asking for gap_layers across it refined the whole
    // air ball: benchmark32 at size 20 went from 47k to 524k tets).
    const bool air_high = is_air(face.label_high);
    if (air_high == is_air(face.label_low) || (air_high ? face.label_low : face.label_high) < 0)
      continue;
    // Nor is the air between a part and an air part (a refinement region such as the space
    // over an actuator's coils, which must keep clear of a turning rotor): resolving a 0.5 mm
    // layer under a 10 mm sphere that way asked for 20 M tetrahedra.
    if (rules.geo.parts[static_cast<std::size_t>(air_high ? face.label_low : face.label_high)].air)
      continue;
    const double side = air_high ? 1.0 : -1.0;
    // Gaps narrower than a tenth of the soup spacing are below the resolution of the coarse
    // triangles the rays are cast against.
    const double min_gap = 0.1 * fs.soup_spacing[f];
    auto gap = [&](const Vec3& x) {
      const Vec3 n = side * face_normal(fr, face, x);
      int hit = -1;
      double w = soup.distance_to_face(x + eps * n, n, min_gap, &hit, true) + eps;
      if (hit >= 0 && is_air_part(rules.geo, dec.faces[hit]))
        w = std::numeric_limits<double>::infinity();
      return std::tuple{w, n, hit};
    };
    // Coarse pass: the narrowest gap seen from this face decides the fine sample spacing.
    double narrowest = std::numeric_limits<double>::infinity();
    for (const Vec3& x : soup.samples()[f].points) {
      check_not_coincident(rules.geo, dec, soup, face, x, side * face_normal(fr, face, x), eps,
                           intrinsic(x));
      const auto [w, n, hit] = gap(x);
      if (rules.scale * w / layers < intrinsic(x))
        narrowest = std::min(narrowest, w);
      const double across = std::min(rules.scale * w / layers, intrinsic(x));
      if (unresolved && hit >= 0 && std::isfinite(w) && across > order * w) {
        const GridFace3D& other = dec.faces[static_cast<std::size_t>(hit)];
        const int self = air_high ? face.label_low : face.label_high;
        const int them = is_air(other.label_low) ? other.label_high : other.label_low;
        if (them >= 0 && them != self) {
          auto& seen = (*unresolved)[{std::min(self, them), std::max(self, them)}];
          if (seen.width == 0 || w < seen.width)
            seen = {w, across, x + n * (w / 2)};
        }
      }
    }
    if (!std::isfinite(narrowest))
      continue;
    const double step = narrowest / layers;
    for (const Vec3& x : sample_face(fr, face, std::min(step, fs.spacing[f])).points) {
      const auto [w, n, hit] = gap(x);
      const double h = rules.scale * w / layers;
      if (h >= intrinsic(x))
        continue;
      for (int k = 0; k <= layers; ++k)
        field.add_source(x + n * (w * k / layers), gap_source_factor * h);
    }
  }
}

// --- TetGen ------------------------------------------------------------------------------

// TetGen's refinement callback carries no user pointer; the field in use is published here for
// the duration of one tetrahedralize() call on this thread, with the last evaluated point.
struct FieldCache {
  const SizeField3D* field = nullptr;
  Vec3 x = Vec3::Constant(std::numeric_limits<double>::infinity());
  double h = 0;
};
thread_local FieldCache active;

bool tet_unsuitable(REAL* a, REAL* b, REAL* c, REAL* d, REAL*, REAL) {
  const Vec3 p[4] = {Vec3(a[0], a[1], a[2]), Vec3(b[0], b[1], b[2]), Vec3(c[0], c[1], c[2]),
                     Vec3(d[0], d[1], d[2])};
  double longest2 = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest2 = std::max(longest2, (p[i] - p[j]).squaredNorm());
  const SizeField3D& field = *active.field;
  const double hmin = field.min_size();
  if (longest2 <= hmin * hmin)
    return false;
  const Vec3 centre = (p[0] + p[1] + p[2] + p[3]) / 4;
  // TetGen checks neighbouring tets in turn: the field is grading-Lipschitz, so the last value
  // often decides without a new evaluation (the computed field is within size_field_slack of
  // the exact one).
  const double dist = (centre - active.x).norm();
  const double lower = (1 - size_field_slack) * active.h - field.grading() * dist;
  if (lower > 0 && longest2 <= lower * lower)
    return false;
  const double upper = active.h + field.grading() * dist;
  if (std::isfinite(upper) && longest2 > upper * upper)
    return true;
  active.x = centre;
  active.h = field(centre);
  return longest2 > active.h * active.h;
}

struct ActiveField {
  explicit ActiveField(const SizeField3D& f) { active = {&f}; }
  ~ActiveField() { active = {}; }
  ActiveField(const ActiveField&) = delete;
  ActiveField& operator=(const ActiveField&) = delete;
};

double attribute_of(int label) {
  return label >= 0 ? label + 1 : label;
}

int label_of(double attribute) {
  const int a = static_cast<int>(std::lround(attribute));
  if (a >= 1)
    return a - 1;
  if (a == region_background_3d || a == region_shell_3d)
    return a;
  throw MeshError("", "", "internal: a region of the tetrahedral mesh has no label");
}

std::string tetgen_failure(int code) {
  switch (code) {
  case 1:
    return "out of memory";
  case 3:
    return "the surface mesh intersects itself (parts too close or overlapping)";
  case 4:
    return "a very small input feature (parts or bounds closer than the tolerance)";
  case 5:
    return "two nearly coincident surface facets";
  case 10:
    return "invalid input";
  default:
    return "internal error " + std::to_string(code);
  }
}

// Seeds one region point on each side of every interface face, just off its first triangle,
// with the region's label and volume bound (that of a regular tet of the region size). For a
// piece of a split domain (surf: the piece's surface mesh), only the seeds inside the piece:
// on the cut, the side towards it (a seed beyond the cut would be outside the piece's volume).
void add_region_seeds(const GridDecomposition3D& dec, const SurfaceMesh3D& surf,
                      const SizeRules& rules, tetgenio& in, const DomainSplit3D* split = nullptr,
                      int piece = 0) {
  std::vector<std::array<double, 5>> seeds;
  std::vector<bool> seen(dec.faces.size(), false);
  for (std::size_t t = 0; t < surf.triangles.size(); ++t) {
    const int f = surf.triangle_face[t];
    if (f < 0)
      continue; // symmetry planes bound the domain; surface parts are seeded by the part
    if (seen[f])
      continue;
    seen[f] = true;
    const GridFace3D& face = dec.faces[f];
    const auto& tri = surf.triangles[t];
    const Vec3 a = surf.points[tri[0]], b = surf.points[tri[1]], c = surf.points[tri[2]];
    const Vec3 centre = (a + b + c) / 3;
    Vec3 n = (b - a).cross(c - a).normalized();
    if (n.dot(face_normal(dec.frames[face.frame], face, centre)) < 0)
      n = -n;
    const double eps = 1e-3 * std::min({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    for (int side : {-1, 1}) {
      const int label = side < 0 ? face.label_low : face.label_high;
      if (label == region_exterior_3d)
        continue;
      if (split && split->on_cut(dec, f) && side != (piece == 0 ? -1 : 1))
        continue;
      const double h = rules.region(label);
      const Vec3 x = centre + side * eps * n;
      seeds.push_back({x.x(), x.y(), x.z(), attribute_of(label), h * h * h / (6 * std::sqrt(2.0))});
    }
  }
  // A surface part: the point inside it that its reader found.
  for (std::size_t p = 0; p < rules.geo.parts.size(); ++p) {
    const Part3D& part = rules.geo.parts[p];
    if (const auto* s = std::get_if<TriangleSurface>(&part.shape)) {
      const Vec3 x = part.placement.to_global(s->inside_point);
      if (split && split->piece_of(x) != piece)
        continue;
      const double h = rules.region(static_cast<int>(p));
      seeds.push_back({x.x(), x.y(), x.z(), attribute_of(static_cast<int>(p)),
                       h * h * h / (6 * std::sqrt(2.0))});
    }
  }
  in.numberofregions = static_cast<int>(seeds.size());
  in.regionlist = new REAL[5 * seeds.size()];
  for (std::size_t i = 0; i < seeds.size(); ++i)
    std::copy(seeds[i].begin(), seeds[i].end(), in.regionlist + 5 * i);
}

void fill_plc(const SurfaceMesh3D& surf, tetgenio& in) {
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(surf.points.size());
  in.pointlist = new REAL[3 * surf.points.size()];
  for (std::size_t i = 0; i < surf.points.size(); ++i)
    for (int k = 0; k < 3; ++k)
      in.pointlist[3 * i + k] = surf.points[i][k];
  in.numberoffacets = static_cast<int>(surf.triangles.size());
  in.facetlist = new tetgenio::facet[surf.triangles.size()];
  in.facetmarkerlist = new int[surf.triangles.size()];
  for (std::size_t t = 0; t < surf.triangles.size(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k)
      f.polygonlist[0].vertexlist[k] = surf.triangles[t][k];
    in.facetmarkerlist[t] = surf.triangle_face[t] + 1; // symmetry planes and surface parts: <= 0
  }
}

// TetGen keeps its exact-arithmetic state in globals: exactinit() sets the error bounds and the
// static filters of orient3d/insphere from each call's bounding box. Two meshes built at once
// (sweep positions, study designs on a thread pool) overwrite each other's filters, and a
// filter sized for a smaller box lets a wrong predicate sign through (seen: a two-thread FE
// sweep whose mesh, and result, differed between runs). One mesh at a time: a split mesh's two
// pieces share the filters of the whole box under this lock (tetgen_shared_state.hpp).
std::mutex& tetgen_lock() {
  static std::mutex m;
  return m;
}

// One tetrahedralize() call, the caller holding tetgen_lock().
void tetrahedralize_locked(const Geometry3D& geo, tetgenio& in, tetgenio& out,
                           const SizeField3D& field) {
  const double ratio = geo.options.radius_edge_ratio > 0 ? geo.options.radius_edge_ratio : 1.6;
  // p: PLC, Y: keep the surface mesh (nodes stay on the curved surfaces, shared faces stay
  // shared), q: quality, A/a: region labels and volume bounds, M: no facet merging (the
  // facets are curved-surface triangles), z: zero-based, Q: quiet.
  std::string switches =
      "pYAaMzQq" + std::to_string(ratio) + "/" + std::to_string(min_dihedral_request_deg);
  in.tetunsuitable = &tet_unsuitable;
  tetgenbehavior b;
  if (!b.parse_commandline(switches.data()))
    throw MeshError("", "radius_edge_ratio", "invalid TetGen switches " + switches);
  const ActiveField guard(field);
  // Keeps the interposed terminatetetgen linked in (see tetgen_termination.cpp).
  if (!tetgen_termination_interposed)
    throw MeshError("", "", "internal: TetGen's error path is not interposed");
  try {
    const TetGenErrorScope scope;
    tetrahedralize(&b, &in, &out);
  } catch (int code) {
    throw MeshError("", "", "TetGen failed: " + tetgen_failure(code));
  } catch (const TetGenAssertion& e) {
    throw MeshError("", "", std::string("TetGen failed: ") + e.what());
  }
}

void run_tetgen(const Geometry3D& geo, tetgenio& in, tetgenio& out, const SizeField3D& field) {
  const std::lock_guard<std::mutex> lock(tetgen_lock());
  tetrahedralize_locked(geo, in, out, field);
}

// One piece's volume mesh, its points numbered as in the piece's surface mesh first.
TetPieceMesh3D mesh_piece(const Geometry3D& geo, const GridDecomposition3D& dec,
                          const SizeRules& rules, const DomainSplit3D& split, int piece,
                          const SizeField3D& field) {
  const SurfaceMesh3D& surf = split.pieces[static_cast<std::size_t>(piece)];
  tetgenio in, out;
  fill_plc(surf, in);
  add_region_seeds(dec, surf, rules, in, &split, piece);
  if (piece == 1) {
    // The outer piece has the cut's triangles as an inner boundary, with nothing inside.
    in.numberofholes = 1;
    in.holelist = new REAL[3]{0, 0, 0};
  }
  const TetGenPieceScope own_random;
  tetrahedralize_locked(geo, in, out, field);
  TetPieceMesh3D result;
  result.points.assign(out.pointlist, out.pointlist + 3 * out.numberofpoints);
  result.tets.assign(out.tetrahedronlist,
                     out.tetrahedronlist + out.numberofcorners * out.numberoftetrahedra);
  result.attributes.resize(static_cast<std::size_t>(out.numberoftetrahedra));
  for (int t = 0; t < out.numberoftetrahedra; ++t)
    result.attributes[static_cast<std::size_t>(t)] =
        out.tetrahedronattributelist[out.numberoftetrahedronattributes * t];
  return result;
}

// The pieces' meshes as one TetGen output: the whole surface mesh's points first (in its
// order, as -Y gives them), then each piece's own points.
void stitch_pieces(const SurfaceMesh3D& surf, const DomainSplit3D& split,
                   const std::array<TetPieceMesh3D, 2>& pieces, tetgenio& out) {
  std::vector<double> points;
  for (const Vec3& x : surf.points)
    points.insert(points.end(), {x.x(), x.y(), x.z()});
  std::vector<int> tets;
  std::vector<double> attributes;
  for (std::size_t p = 0; p < 2; ++p) {
    const TetPieceMesh3D& piece = pieces[p];
    const std::vector<int>& whole = split.whole_point[p];
    std::vector<int> index(piece.points.size() / 3);
    for (std::size_t i = 0; i < index.size(); ++i) {
      if (i < whole.size()) {
        index[i] = whole[i];
        continue;
      }
      index[i] = static_cast<int>(points.size() / 3);
      points.insert(points.end(), piece.points.begin() + 3 * static_cast<std::ptrdiff_t>(i),
                    piece.points.begin() + 3 * static_cast<std::ptrdiff_t>(i) + 3);
    }
    for (int v : piece.tets)
      tets.push_back(index[static_cast<std::size_t>(v)]);
    attributes.insert(attributes.end(), piece.attributes.begin(), piece.attributes.end());
  }
  out.numberofpoints = static_cast<int>(points.size() / 3);
  out.pointlist = new REAL[points.size()];
  std::copy(points.begin(), points.end(), out.pointlist);
  out.numberofcorners = 4;
  out.numberoftetrahedra = static_cast<int>(attributes.size());
  out.tetrahedronlist = new int[tets.size()];
  std::copy(tets.begin(), tets.end(), out.tetrahedronlist);
  out.numberoftetrahedronattributes = 1;
  out.tetrahedronattributelist = new REAL[attributes.size()];
  std::copy(attributes.begin(), attributes.end(), out.tetrahedronattributelist);
}

// The two pieces of a split domain in this process: on two threads when there are two and
// TetGen's shared state allows it (tetgen_shared_state.hpp), else one after the other.
std::array<TetPieceMesh3D, 2> mesh_pieces_here(const MeshPiece3D& mesh,
                                               const TetGenSharedFilters& filters) {
  std::array<TetPieceMesh3D, 2> pieces;
  if (available_threads() < 2 || !tetgen_calls_may_overlap(filters)) {
    for (int p = 0; p < 2; ++p)
      pieces[static_cast<std::size_t>(p)] = mesh(p);
    return pieces;
  }
  std::exception_ptr inner_failure;
  std::thread inner([&] {
    try {
      pieces[0] = mesh(0);
    } catch (...) {
      inner_failure = std::current_exception();
    }
  });
  try {
    pieces[1] = mesh(1);
  } catch (...) {
    inner.join();
    throw;
  }
  inner.join();
  if (inner_failure)
    std::rethrow_exception(inner_failure);
  return pieces;
}

// The two pieces of a split domain, meshed where `runner` says (here when it is empty), and
// stitched. The pieces' meshes do not depend on where: each call has its own random generator
// and all use the whole domain's predicate filters (tetgen_shared_state.hpp).
void run_tetgen_split(const Geometry3D& geo, const GridDecomposition3D& dec, const SizeRules& rules,
                      const SurfaceMesh3D& surf, const DomainSplit3D& split,
                      const SizeField3D& field, const PieceRunner3D& runner, tetgenio& out) {
  Eigen::AlignedBox3d box;
  for (const Vec3& x : surf.points)
    box.extend(x);
  const Vec3 extent = box.sizes();
  const std::lock_guard<std::mutex> lock(tetgen_lock());
  const TetGenSharedFilters filters(extent.x(), extent.y(), extent.z());
  const MeshPiece3D mesh = [&](int p) { return mesh_piece(geo, dec, rules, split, p, field); };
  const std::array<TetPieceMesh3D, 2> pieces =
      runner ? runner(mesh) : mesh_pieces_here(mesh, filters);
  stitch_pieces(surf, split, pieces, out);
}

Mesh3D collect_mesh(const Geometry3D& geo, const GridDecomposition3D& dec,
                    const SurfaceMesh3D& surf, const tetgenio& out) {
  Mesh3D m;
  m.nodes.resize(out.numberofpoints);
  for (int i = 0; i < out.numberofpoints; ++i)
    m.nodes[i] = Vec3(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]);
  m.part_volumes.assign(geo.parts.size(), 0.0);
  m.tets.resize(out.numberoftetrahedra);
  m.tet_part.resize(out.numberoftetrahedra);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    std::array<int, 4> v;
    for (int k = 0; k < 4; ++k)
      v[k] = out.tetrahedronlist[out.numberofcorners * t + k];
    double vol = tet_volume(m.nodes[v[0]], m.nodes[v[1]], m.nodes[v[2]], m.nodes[v[3]]);
    if (vol < 0) {
      std::swap(v[2], v[3]);
      vol = -vol;
    }
    m.tets[t] = v;
    const int label = label_of(out.tetrahedronattributelist[out.numberoftetrahedronattributes * t]);
    m.tet_part[t] = label;
    if (label >= 0)
      m.part_volumes[label] += vol;
  }
  // -Y keeps every input point, in input order, at the front of the output.
  for (std::size_t i = 0; i < surf.points.size(); ++i)
    if ((m.nodes[i] - surf.points[i]).norm() > 1e-12 * geo.outer.radius)
      throw MeshError("", "", "internal: TetGen renumbered the surface points");
  m.symmetry = geo.symmetry;
  m.symmetry_faces.resize(geo.symmetry.size());
  for (std::size_t t = 0; t < surf.triangles.size(); ++t) {
    if (is_symmetry_face(surf.triangle_face[t])) {
      m.symmetry_faces[symmetry_plane_of(surf.triangle_face[t])].push_back(surf.triangles[t]);
      continue;
    }
    if (surf.triangle_face[t] < 0)
      continue; // a surface part's: inside the domain
    const GridFace3D& face = dec.faces[surf.triangle_face[t]];
    if (face.label_high != region_exterior_3d)
      continue;
    auto tri = surf.triangles[t];
    const Vec3 a = m.nodes[tri[0]], b = m.nodes[tri[1]], c = m.nodes[tri[2]];
    if ((b - a).cross(c - a).dot(a + b + c) < 0)
      std::swap(tri[1], tri[2]);
    m.outer_faces.push_back(tri);
  }
  if (geo.outer.kind == OuterKind3D::open) {
    m.shell_inner_radius = geo.outer.radius;
    m.shell_outer_radius = geo.outer.shell_ratio * geo.outer.radius;
  }
  order_spatially(m); // TetGen's insertion order scatters every matrix row's columns
  m.quality = compute_quality_3d(m.nodes, m.tets);
  return m;
}

// Mesh3D::tet_size: what tet_unsuitable and the regions' volume bounds asked for. On all
// cores: a size-field query per tet (1.6 M on benchmark32) is a second of the serial mesher.
std::vector<double> requested_sizes(const Mesh3D& m, const SizeRules& rules,
                                    const SizeField3D& field) {
  std::vector<double> h(m.n_tets());
  parallel_blocks(m.n_tets(), 4096, element_loop_threads(m.n_tets()),
                  [&](std::size_t, std::size_t lo, std::size_t hi) {
                    for (std::size_t t = lo; t < hi; ++t) {
                      const auto& k = m.tets[t];
                      const Vec3 centre =
                          (m.nodes[k[0]] + m.nodes[k[1]] + m.nodes[k[2]] + m.nodes[k[3]]) / 4;
                      h[t] = std::min(field(centre), rules.region(m.tet_part[t]));
                    }
                  });
  return h;
}

// Points on the triangle abc at most about `step` apart (a barycentric grid).
std::vector<Vec3> triangle_samples(const Vec3& a, const Vec3& b, const Vec3& c, double step) {
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const int n = std::max(1, static_cast<int>(std::ceil(longest / step)));
  std::vector<Vec3> out;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      out.push_back(a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n));
  return out;
}

// The size rules on the triangles of the surface parts, as on a built-in part's faces: the
// smaller of the part's and the air's region size, sampled like them (their facets are the
// geometry, so no chord limit applies), and the gap rule across the air to every other part
// (rays along the outward normal; a part's gaps to itself, across a concave edge, are not
// counted, or every such edge would ask for ever smaller elements towards it).
void add_surface_part_sources(const GridDecomposition3D& dec, const SizeRules& rules,
                              const FaceSoup3D& soup, SizeField3D& field) {
  const Geometry3D& geo = rules.geo;
  const int layers = std::max(1, geo.options.gap_layers);
  const double eps = 1e-7 * geo.outer.radius;
  std::unique_ptr<SurfacePartRays3D> rays;
  for (std::size_t p = 0; p < geo.parts.size(); ++p) {
    const Part3D& part = geo.parts[p];
    const auto* s = std::get_if<TriangleSurface>(&part.shape);
    if (!s)
      continue;
    if (!rays)
      rays = std::make_unique<SurfacePartRays3D>(geo, dec, soup);
    const int self = static_cast<int>(p);
    const double h = std::min(rules.region(self), rules.region(region_background_3d));
    const double spacing = sample_fraction * h;
    for (const auto& t : s->triangles) {
      const Vec3 a = part.placement.to_global(s->points[t[0]]);
      const Vec3 b = part.placement.to_global(s->points[t[1]]);
      const Vec3 c = part.placement.to_global(s->points[t[2]]);
      const Vec3 n = (b - a).cross(c - a).normalized(); // outward (the reader's orientation)
      for (const Vec3& x : triangle_samples(a, b, c, spacing))
        field.add_source(x, h);
      if (part.air)
        continue; // an air part bounds no gap (see add_surface_sources)
      auto gap = [&](const Vec3& x) {
        return rays->gap(self, x + eps * n, n, 0.1 * spacing) + eps;
      };
      double narrowest = std::numeric_limits<double>::infinity();
      for (const Vec3& x : triangle_samples(a, b, c, spacing))
        if (const double w = gap(x); rules.scale * w / layers < h)
          narrowest = std::min(narrowest, w);
      if (!std::isfinite(narrowest))
        continue;
      for (const Vec3& x : triangle_samples(a, b, c, std::min(narrowest / layers, spacing))) {
        const double w = gap(x), across = rules.scale * w / layers;
        if (across >= h)
          continue;
        for (int k = 0; k <= layers; ++k)
          field.add_source(x + n * (w * k / layers), gap_source_factor * across);
      }
    }
  }
}

// The size field capped by the region size of the part (or air) at x: TetGen's volume bound
// keeps elements inside a part no larger than its region size even far from any surface.
MeshEstimate3D estimate_mesh_size(const Geometry3D& geo, const SizeRules& rules,
                                  const SizeField3D& field,
                                  const std::vector<double>& within_radii = {}) {
  const bool open = geo.outer.kind == OuterKind3D::open;
  auto size = [&](const Vec3& x) {
    double region =
        rules.region(open && x.norm() > geo.outer.radius ? region_shell_3d : region_background_3d);
    for (std::size_t i = 0; i < geo.parts.size(); ++i)
      if (part_contains(geo.parts[i], x, 0)) {
        region = rules.region(static_cast<int>(i));
        break;
      }
    return std::min(field(x), region);
  };
  const double ball = geo.outer.radius * (open ? geo.outer.shell_ratio : 1.0);
  // The size field of a symmetric model is symmetric: its share is the ball's over the factor.
  MeshEstimate3D e = estimate_mesh_3d(size, ball, within_radii);
  const double factor = symmetry_factor(geo.symmetry);
  e.tetrahedra /= factor;
  e.nodes /= factor;
  for (double& n : e.tetrahedra_within)
    n /= factor;
  return e;
}

SizeField3D build_size_field(const GridDecomposition3D& dec, const SizeRules& rules,
                             const FaceSizing& fs, const FaceSoup3D& soup,
                             const std::vector<ProbeSurface>& refine,
                             UnresolvedGaps* unresolved = nullptr) {
  SizeField3D field(grading);
  add_surface_sources(dec, rules, fs, soup, field, unresolved);
  add_surface_part_sources(dec, rules, soup, field);
  if (rules.geo.options.probe_size > 0)
    for (const ProbeSurface& p : refine)
      field.add_probe(p, rules.scale * rules.geo.options.probe_size);
  if (const auto& adaptive = rules.geo.options.refine_sizes)
    for (const SizeSample3D& s : *adaptive)
      field.add_source(s.x, s.h);
  field.build();
  return field;
}

// The estimate for the geometry with every size multiplied by `factor` (what a larger
// --mesh-scale would give: chord limits do not grow with it, so the count need not fall as
// factor^-3).
MeshEstimate3D estimate_scaled(const Geometry3D& geo, const std::vector<ProbeSurface>& refine,
                               double factor) {
  Geometry3D g = geo;
  g.options.size_scale = (geo.options.size_scale > 0 ? geo.options.size_scale : 1.0) * factor;
  const GridDecomposition3D dec = decompose_geometry_3d(g);
  const SizeRules rules(g);
  const FaceSizing fs = face_sizing(dec, rules);
  const FaceSoup3D soup(dec, fs.soup_spacing);
  return estimate_mesh_size(g, rules, build_size_field(dec, rules, fs, soup, refine));
}

} // namespace

Mesh3D build_mesh_3d(const Geometry3D& geo, const std::vector<ProbeSurface>& refine,
                     const MeshSizeCheck& check, const PieceRunner3D& pieces) {
  const GridDecomposition3D dec = decompose_geometry_3d(geo);
  const SizeRules rules(geo);
  const FaceSizing fs = face_sizing(dec, rules);
  const FaceSoup3D soup(dec, fs.soup_spacing);
  soup.check_parts(geo);
  check_surface_parts(geo, soup);

  UnresolvedGaps unresolved;
  const SizeField3D field = build_size_field(dec, rules, fs, soup, refine, &unresolved);
  // An adaptive pass's sizes (options.refine_sizes) may resolve a gap that the case's sizes
  // at this --mesh-scale leave coarse. The field holds the gap's own sources shrunk by
  // gap_source_factor (what TetGen delivers for them is their size): undone here to compare
  // like with like.
  if (geo.options.refine_sizes)
    for (auto& [pair, gap] : unresolved)
      gap.across = std::min(gap.across, field(gap.middle) / gap_source_factor);
  // The estimate is needed for the split only where a sphere to split at exists.
  const std::vector<double> cuts = split_sphere_radii(geo, dec);
  std::optional<double> cut;
  if (check || !cuts.empty()) {
    const MeshEstimate3D estimate = estimate_mesh_size(geo, rules, field, cuts);
    if (check)
      check(estimate,
            [&](double factor) { return estimate_scaled(geo, refine, factor).tetrahedra; });
    cut = choose_split_radius(cuts, estimate, geo.options.split_min_tetrahedra);
  }

  const double outer =
      geo.outer.radius * (geo.outer.kind == OuterKind3D::open ? geo.outer.shell_ratio : 1.0);
  const SurfaceMesh3D surf = mesh_surfaces_3d(
      geo, dec, field, 1e-9 * geo.outer.radius * geo.outer.shell_ratio, geo.symmetry, outer);
  tetgenio in, out;
  const std::optional<DomainSplit3D> split =
      cut ? split_surface_mesh(dec, surf, *cut) : std::nullopt;
  if (split) {
    run_tetgen_split(geo, dec, rules, surf, *split, field, pieces, out);
  } else {
    fill_plc(surf, in);
    add_region_seeds(dec, surf, rules, in);
    run_tetgen(geo, in, out, field);
  }
  Mesh3D m = collect_mesh(geo, dec, surf, out);
  m.split_radius = split ? split->radius : 0.0;
  std::vector<std::string> part_names;
  for (const auto& part : geo.parts)
    part_names.push_back(part.name);
  m.warnings = unresolved_gap_warnings(part_names, geo.options.element_order,
                                       geo.options.gap_layers, rules.scale, unresolved);
  m.tet_size = requested_sizes(m, rules, field);
  return m;
}

MeshEstimate3D estimate_geometry_mesh_3d(const Geometry3D& geo,
                                         const std::vector<ProbeSurface>& refine,
                                         const MeshSizeCheck& check) {
  const GridDecomposition3D dec = decompose_geometry_3d(geo);
  const SizeRules rules(geo);
  const FaceSizing fs = face_sizing(dec, rules);
  const FaceSoup3D soup(dec, fs.soup_spacing);
  const MeshEstimate3D e =
      estimate_mesh_size(geo, rules, build_size_field(dec, rules, fs, soup, refine));
  if (check)
    check(e, [&](double factor) { return estimate_scaled(geo, refine, factor).tetrahedra; });
  return e;
}

} // namespace magfem
