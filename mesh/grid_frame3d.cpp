#include "mesh/grid_frame3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "mesh/face_chart3d.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/surface_index3d.hpp"

namespace magfem {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;
constexpr double angle_tol = 1e-9; // rad: breakpoints closer than this are one breakpoint
// Default angular breakpoints: every cell of a periodic axis spans at most 90 deg, so every
// face is a simple quadrilateral patch and no curve closes on itself.
constexpr std::array<double, 4> quarter_turns{0, std::numbers::pi / 2, std::numbers::pi,
                                              3 * std::numbers::pi / 2};

double wrap_angle(double a) {
  a = std::fmod(a, two_pi);
  return a < 0 ? a + two_pi : a;
}

// Sorts and merges breakpoints closer than tol; on a periodic axis values near 2 pi merge
// with 0.
std::vector<double> unique_breaks(std::vector<double> b, double tol, bool periodic) {
  std::sort(b.begin(), b.end());
  std::vector<double> out;
  for (double v : b)
    if (out.empty() || v - out.back() > tol)
      out.push_back(v);
  if (periodic && out.size() > 1 && two_pi - out.back() <= tol)
    out.pop_back();
  return out;
}

// Parameter ranges of a part in its frame's grid coordinates; periodic axes hold
// [start, start + length] with start in [0, 2 pi) and full = length >= 2 pi.
struct GridRanges {
  std::array<double, 3> lo{}, hi{};
  std::array<bool, 3> full{false, false, false};
};

bool in_range(const GridRanges& r, int axis, double v, bool periodic) {
  if (r.full[axis])
    return true;
  if (!periodic)
    return v >= r.lo[axis] && v <= r.hi[axis];
  return wrap_angle(v - r.lo[axis]) <= r.hi[axis] - r.lo[axis];
}

bool same_rotation(const Mat3& a, const Mat3& b) {
  return (a - b).cwiseAbs().maxCoeff() < 1e-9;
}

void require(bool ok, const Part3D& part, const std::string& field, const std::string& msg) {
  if (!ok)
    throw MeshError(part.name, field, msg);
}

void validate_placement(const Part3D& part) {
  const Mat3& r = part.placement.rotation;
  require(r.allFinite() && part.placement.translation.allFinite(), part, "placement",
          "placement has non-finite entries");
  require((r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-9 &&
              r.determinant() > 0,
          part, "placement", "rotation is not a proper orthogonal matrix");
  require(std::isfinite(part.max_size) && part.max_size >= 0, part, "max_size",
          "max_size must be >= 0 (0 = default size)");
}

void validate_shape(const Part3D& part, const SphericalSegment& s) {
  require(std::isfinite(s.r_inner) && s.r_inner >= 0, part, "r_inner", "r_inner must be >= 0");
  require(std::isfinite(s.r_outer) && s.r_outer > s.r_inner, part, "r_outer",
          "r_outer must exceed r_inner");
  require(std::isfinite(s.theta_min) && s.theta_min >= -angle_tol, part, "theta_min",
          "theta_min must be >= 0");
  require(std::isfinite(s.theta_max) && s.theta_max <= std::numbers::pi + angle_tol, part,
          "theta_max", "theta_max must be <= pi");
  require(s.theta_max - s.theta_min > angle_tol, part, "theta_max",
          "theta_max must exceed theta_min");
  require(std::isfinite(s.phi_min) && std::isfinite(s.phi_max) && s.phi_max - s.phi_min > angle_tol,
          part, "phi_max", "phi_max must exceed phi_min");
  require(s.phi_max - s.phi_min <= two_pi + angle_tol, part, "phi_max", "phi range exceeds 2 pi");
}

void validate_shape(const Part3D& part, const Cylinder& c) {
  require(std::isfinite(c.r_inner) && c.r_inner >= 0, part, "r_inner", "r_inner must be >= 0");
  require(std::isfinite(c.r_outer) && c.r_outer > c.r_inner, part, "r_outer",
          "r_outer must exceed r_inner");
  require(std::isfinite(c.height) && c.height > 0, part, "height", "height must be > 0");
}

void validate_shape(const Part3D&, const TriangleSurface&) {} // checked when read

void validate_shape(const Part3D& part, const Box& b) {
  require(b.size.allFinite() && b.size.minCoeff() > 0, part, "size",
          "every edge of a box must be > 0");
}

// Nominal facet length of a part's surface: the smaller of its size and the air's.
double nominal_size(const Geometry3D& geo, const Part3D& part) {
  const MeshOptions3D& o = geo.options;
  const double scale = o.size_scale > 0 ? o.size_scale : 1.0;
  const double air = o.default_size > 0 ? o.default_size : geo.outer.radius / 8;
  return scale * std::min(part.max_size > 0 ? part.max_size : air, air);
}

// Largest sagitta a facet of a part surface with curvature radius `radius` may have: facets
// are at most the smaller of the part's and the air's size long (h^2 / (6 R)) and, with a
// chord tolerance, no deeper than it (scaled like the chord limit when size_scale < 1).
double max_sagitta(const Geometry3D& geo, const Part3D& part, double radius) {
  const MeshOptions3D& o = geo.options;
  const double scale = o.size_scale > 0 ? o.size_scale : 1.0;
  const double h = nominal_size(geo, part);
  double s = h * h / (6 * radius);
  if (o.chord_tolerance > 0)
    s = std::min(s, o.chord_tolerance * std::min(scale, 1.0) * std::min(scale, 1.0));
  return s;
}

// A shell (spherical or cylindrical) thinner than 1.5 times the sagitta bound of its facets
// (the chord limit keeps the real sagitta below 0.81 of that bound): the
// faceted outer surface would dip through the inner one, TetGen would find the surfaces
// crossing and fail in a way that aborts inside the library (measured: a 10 um shell of
// radius 10 mm at chord_tolerance 50 um). Caught here with the part's name instead.
void validate_thickness(const Geometry3D& geo, const Part3D& part) {
  double r_inner = 0, r_outer = 0;
  if (const auto* s = std::get_if<SphericalSegment>(&part.shape)) {
    r_inner = s->r_inner;
    r_outer = s->r_outer;
  } else if (const auto* c = std::get_if<Cylinder>(&part.shape)) {
    r_inner = c->r_inner;
    r_outer = c->r_outer;
  }
  if (!(r_inner > 0))
    return;
  const double sagitta = max_sagitta(geo, part, r_outer);
  const double t = r_outer - r_inner;
  if (t < 1.5 * sagitta) {
    char msg[400];
    std::snprintf(msg, sizeof msg,
                  "the shell is %.3g m thick, less than 1.5 times the depth its facets may have "
                  "(%.3g m): its faceted surfaces would cross. Lower mesh chord_tolerance below "
                  "%.3g m (or the part's mesh size) or make the shell thicker",
                  t, sagitta, t / 4);
    throw MeshError(part.name, "r_inner", msg);
  }
}

// Whether the ranges of two parts of one frame overlap on `axis` (touching counts).
bool ranges_overlap(const GridRanges& a, const GridRanges& b, int axis, bool periodic) {
  return in_range(a, axis, b.lo[axis], periodic) || in_range(b, axis, a.lo[axis], periodic);
}

// Concentric curved faces of two parts (spheres or cylinders of one frame, facing each other)
// closer than a thousandth of their facet length: TetGen cannot mesh the slab between them
// (measured: spheres of 10 and 10.00001 mm crashed the solve with a segmentation fault in
// the assembly). The ray test of the mesher sees planar faces only (mesher3d.cpp); the
// radial bounds of one frame are exact, so these are compared here. The same fraction as
// there: wider gaps are the gap rule's to resolve.
constexpr double coincident_fraction = 1e-3;

void validate_radial_gaps(const Geometry3D& geo, const GridFrame3D& f,
                          const std::vector<GridRanges>& rs, double len_tol) {
  if (f.kind == GridKind3D::cartesian)
    return;
  for (std::size_t i = 0; i < rs.size(); ++i)
    for (std::size_t j = i + 1; j < rs.size(); ++j) {
      bool facing = true;
      for (int a = 1; a < 3; ++a)
        facing = facing && ranges_overlap(rs[i], rs[j], a, f.periodic[a]);
      if (!facing)
        continue;
      const Part3D& pi = geo.parts[f.parts[i]];
      const Part3D& pj = geo.parts[f.parts[j]];
      const double h = std::min(nominal_size(geo, pi), nominal_size(geo, pj));
      for (double u : {rs[i].lo[0], rs[i].hi[0]})
        for (double v : {rs[j].lo[0], rs[j].hi[0]}) {
          const double gap = std::abs(u - v);
          if (gap <= len_tol || gap >= coincident_fraction * h || std::min(u, v) <= 0)
            continue;
          char msg[400];
          std::snprintf(msg, sizeof msg,
                        "its curved face at radius %.9g m lies %.3g m from the face of part "
                        "'%s' at radius %.9g m (the mesh size there is %.3g m): nearly "
                        "coincident faces cannot be meshed; make them touch or move them at "
                        "least a thousandth of the mesh size apart",
                        u, gap, pj.name.c_str(), v, h);
          throw MeshError(pi.name, u == rs[i].lo[0] ? "r_inner" : "r_outer", msg);
        }
    }
}

GridKind3D kind_of(const Shape3D& s) {
  if (std::holds_alternative<SphericalSegment>(s))
    return GridKind3D::spherical;
  if (std::holds_alternative<Cylinder>(s))
    return GridKind3D::cylindrical;
  return GridKind3D::cartesian;
}

// Offset of `p` expressed in the frame `f` if `p` can share its grid, else false.
// Spherical: same centre and orientation; cylindrical: same axis line and orientation (offset
// along z); cartesian: same orientation (any offset).
bool frame_offset(const GridFrame3D& f, const Placement& p, double len_tol, Vec3& offset) {
  if (!same_rotation(f.placement.rotation, p.rotation))
    return false;
  offset = f.placement.rotation.transpose() * (p.translation - f.placement.translation);
  switch (f.kind) {
  case GridKind3D::spherical:
    return offset.norm() <= len_tol;
  case GridKind3D::cylindrical:
    return offset.head<2>().norm() <= len_tol;
  case GridKind3D::cartesian:
    return true;
  }
  return false;
}

GridRanges ranges_in_frame(const Part3D& part, const Vec3& off) {
  GridRanges g;
  if (const auto* s = std::get_if<SphericalSegment>(&part.shape)) {
    g.lo = {s->r_inner, std::max(0.0, s->theta_min), wrap_angle(s->phi_min)};
    g.hi = {s->r_outer, std::min(std::numbers::pi, s->theta_max),
            wrap_angle(s->phi_min) + (s->phi_max - s->phi_min)};
    g.full[2] = s->phi_max - s->phi_min >= two_pi - angle_tol;
  } else if (const auto* c = std::get_if<Cylinder>(&part.shape)) {
    g.lo = {c->r_inner, 0, off.z()};
    g.hi = {c->r_outer, two_pi, off.z() + c->height};
    g.full[1] = true;
  } else {
    const Vec3 h = std::get<Box>(part.shape).size / 2;
    for (int a = 0; a < 3; ++a)
      g.lo[a] = off[a] - h[a], g.hi[a] = off[a] + h[a];
  }
  return g;
}

using ExtraBreaks = std::array<std::vector<double>, 3>;

void set_breaks(GridFrame3D& f, const std::vector<GridRanges>& rs, double len_tol,
                const ExtraBreaks& extra) {
  for (int a = 0; a < 3; ++a) {
    std::vector<double> b;
    const bool angular =
        (f.kind == GridKind3D::spherical && a > 0) || (f.kind == GridKind3D::cylindrical && a == 1);
    if (f.periodic[a])
      b.assign(quarter_turns.begin(), quarter_turns.end());
    if (f.kind == GridKind3D::spherical && a == 1)
      b = {0, std::numbers::pi / 2, std::numbers::pi};
    b.insert(b.end(), extra[a].begin(), extra[a].end());
    for (const GridRanges& r : rs) {
      if (r.full[a])
        continue;
      b.push_back(f.periodic[a] ? wrap_angle(r.lo[a]) : r.lo[a]);
      b.push_back(f.periodic[a] ? wrap_angle(r.hi[a]) : r.hi[a]);
    }
    f.breaks[a] = unique_breaks(b, angular ? angle_tol : len_tol, f.periodic[a]);
  }
}

void label_cells(GridFrame3D& f, const Geometry3D& geo, const std::vector<GridRanges>& rs) {
  f.labels.assign(static_cast<std::size_t>(f.n_cells(0)) * f.n_cells(1) * f.n_cells(2),
                  region_background_3d);
  for (int i = 0; i < f.n_cells(0); ++i)
    for (int j = 0; j < f.n_cells(1); ++j)
      for (int k = 0; k < f.n_cells(2); ++k) {
        const std::array<int, 3> c{i, j, k};
        int& lab = f.labels[f.cell_index(i, j, k)];
        for (std::size_t n = 0; n < f.parts.size(); ++n) {
          bool inside = true;
          for (int a = 0; a < 3 && inside; ++a)
            inside = in_range(rs[n], a, 0.5 * (f.lo(a, c[a]) + f.hi(a, c[a])), f.periodic[a]);
          if (!inside)
            continue;
          const int p = f.parts[n];
          if (lab >= 0)
            throw MeshError(geo.parts[p].name, "", "intersects part '" + geo.parts[lab].name + "'");
          lab = p;
        }
      }
}

// Frame 0 also holds the domain ball and, for an open boundary, the shell around it.
void label_outer(GridFrame3D& f, const Geometry3D& geo) {
  const double r1 = geo.outer.radius;
  const bool open = geo.outer.kind == OuterKind3D::open;
  const double r2 = open ? geo.outer.shell_ratio * r1 : r1;
  f.label_above = region_exterior_3d;
  for (int i = 0; i < f.n_cells(0); ++i) {
    const double mid = 0.5 * (f.lo(0, i) + f.hi(0, i));
    if (mid < r1)
      continue;
    for (int j = 0; j < f.n_cells(1); ++j)
      for (int k = 0; k < f.n_cells(2); ++k) {
        int& lab = f.labels[f.cell_index(i, j, k)];
        if (lab >= 0)
          throw MeshError(geo.parts[lab].name, "",
                          "extends beyond the domain ball of radius " + std::to_string(r1) + " m");
        lab = (open && mid < r2) ? region_shell_3d : region_exterior_3d;
      }
  }
}

bool degenerate_face(const GridFrame3D& f, int axis, double v) {
  if (f.kind == GridKind3D::spherical && axis == 0)
    return v <= 0;
  if (f.kind == GridKind3D::spherical && axis == 1)
    return v <= angle_tol || v >= std::numbers::pi - angle_tol;
  if (f.kind == GridKind3D::cylindrical && axis == 0)
    return v <= 0;
  return false;
}

void collect_faces(const GridFrame3D& f, int frame, std::vector<GridFace3D>& out) {
  for (int a = 0; a < 3; ++a) {
    const int b1 = (a + 1) % 3, b2 = (a + 2) % 3;
    const int n_faces = static_cast<int>(f.breaks[a].size());
    for (int idx = 0; idx < n_faces; ++idx) {
      if (degenerate_face(f, a, f.breaks[a][idx]))
        continue;
      for (int c1 = 0; c1 < f.n_cells(b1); ++c1)
        for (int c2 = 0; c2 < f.n_cells(b2); ++c2) {
          std::array<int, 3> low{}, high{};
          low[a] = f.periodic[a] ? (idx + n_faces - 1) % n_faces : idx - 1;
          high[a] = idx;
          low[b1] = high[b1] = c1;
          low[b2] = high[b2] = c2;
          const int ll = f.label(low), lh = f.label(high);
          if (ll != lh)
            out.push_back({frame, a, idx, {c1, c2}, ll, lh});
        }
    }
  }
}

double domain_length(const Geometry3D& geo) {
  return std::max(geo.outer.radius, 1e-12);
}

void validate_outer(const Geometry3D& geo) {
  if (!(std::isfinite(geo.outer.radius) && geo.outer.radius > 0))
    throw MeshError("", "radius", "outer boundary radius must be > 0");
  if (geo.outer.kind == OuterKind3D::open && !(geo.outer.shell_ratio > 1))
    throw MeshError("", "shell_ratio", "open boundary needs shell_ratio > 1");
}

// Breakpoints that make a symmetry plane a coordinate surface of the frame, so that every
// cell lies on one side of it (false when the frame's grid cannot follow the plane: a box or
// cylinder tilted against it, a sphere centred off it). Plane: n . (R q + t) = 0, i.e.
// n_l . q = -d with n_l = R^T n, d = n . t, in the frame's local coordinates q.
bool add_plane_breaks(const GridFrame3D& f, const SymmetryPlane3D& plane, double len_tol,
                      ExtraBreaks& extra) {
  constexpr double aligned = 1e-9;
  const Vec3 n = Vec3::Unit(plane.axis);
  const Vec3 nl = f.placement.rotation.transpose() * n;
  const double d = n.dot(f.placement.translation);
  // Angle of the plane's trace about the local z axis (the plane contains that axis).
  auto trace_breaks = [&](int axis) {
    const double a0 = std::atan2(nl.y(), nl.x()) + std::numbers::pi / 2;
    extra[axis].push_back(wrap_angle(a0));
    extra[axis].push_back(wrap_angle(a0 + std::numbers::pi));
  };
  switch (f.kind) {
  case GridKind3D::cartesian:
    for (int a = 0; a < 3; ++a)
      if (std::abs(nl[a]) > 1 - aligned) {
        extra[a].push_back(-d / nl[a]);
        return true;
      }
    return false;
  case GridKind3D::cylindrical:
    if (std::abs(nl.z()) > 1 - aligned) {
      extra[2].push_back(-d / nl.z());
      return true;
    }
    if (std::abs(nl.z()) < aligned && std::abs(d) <= len_tol) {
      trace_breaks(1);
      return true;
    }
    return false;
  case GridKind3D::spherical:
    if (std::abs(d) > len_tol)
      return false;
    if (std::abs(nl.z()) > 1 - aligned)
      return true; // theta = pi / 2 is always a breakpoint
    if (std::abs(nl.z()) < aligned) {
      trace_breaks(2);
      return true;
    }
    return false;
  }
  return false;
}

// Keeps the faces on the model's side of every symmetry plane: faces beyond a plane, and
// faces lying on it (the mesher covers the plane with its own facets), are dropped. A face
// crossing a plane belongs to a part whose frame could not follow it (add_plane_breaks).
void clip_faces(const Geometry3D& geo, GridDecomposition3D& dec, double tol) {
  if (geo.symmetry.empty())
    return;
  std::vector<GridFace3D> kept;
  for (const GridFace3D& face : dec.faces) {
    const GridFrame3D& fr = dec.frames[face.frame];
    const FaceSamples3D corners = sample_face(fr, face, std::numeric_limits<double>::max());
    double extent = 0;
    for (const Vec3& a : corners.points)
      for (const Vec3& b : corners.points)
        extent = std::max(extent, (a - b).norm());
    const FaceSamples3D s = sample_face(fr, face, std::max(extent / 8, tol));
    bool beyond = false, on_plane = false;
    for (const SymmetryPlane3D& p : geo.symmetry) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const Vec3& x : s.points) {
        lo = std::min(lo, x[p.axis]);
        hi = std::max(hi, x[p.axis]);
      }
      if (lo < -tol && hi > tol) {
        const int part = face.label_low >= 0 ? face.label_low : face.label_high;
        throw MeshError(part >= 0 ? geo.parts[part].name : "", "",
                        std::string("is cut by the symmetry plane ") + axis_name(p.axis) +
                            " = 0 but its axes are not aligned with it (a box or cylinder "
                            "must have an axis along the plane's normal or, for a cylinder, "
                            "in the plane; a sphere must be centred on it)");
      }
      beyond = beyond || lo < -tol;
      on_plane = on_plane || (lo >= -tol && hi <= tol);
    }
    if (!beyond && !on_plane)
      kept.push_back(face);
  }
  dec.faces = std::move(kept);
}

} // namespace

int GridFrame3D::n_cells(int axis) const {
  const int nb = static_cast<int>(breaks[axis].size());
  return periodic[axis] ? nb : std::max(nb - 1, 0);
}

double GridFrame3D::hi(int axis, int i) const {
  const auto& b = breaks[axis];
  if (periodic[axis] && i + 1 == static_cast<int>(b.size()))
    return b[0] + two_pi;
  return b[i + 1];
}

int GridFrame3D::cell_index(int i, int j, int k) const {
  return (i * n_cells(1) + j) * n_cells(2) + k;
}

int GridFrame3D::label(std::array<int, 3> c) const {
  for (int a = 0; a < 3; ++a) {
    if (periodic[a])
      c[a] = (c[a] + n_cells(a)) % n_cells(a);
    if (c[a] < 0)
      return region_background_3d;
    if (c[a] >= n_cells(a))
      return a == 0 ? label_above : region_background_3d;
  }
  return labels[cell_index(c[0], c[1], c[2])];
}

Vec3 GridFrame3D::local_point(const Vec3& q) const {
  switch (kind) {
  case GridKind3D::spherical:
    return q[0] *
           Vec3(std::sin(q[1]) * std::cos(q[2]), std::sin(q[1]) * std::sin(q[2]), std::cos(q[1]));
  case GridKind3D::cylindrical:
    return {q[0] * std::cos(q[1]), q[0] * std::sin(q[1]), q[2]};
  case GridKind3D::cartesian:
    return q;
  }
  return q;
}

Vec3 GridFrame3D::axis_direction(int axis, const Vec3& q) const {
  Vec3 d = Vec3::Unit(axis);
  if (kind == GridKind3D::spherical) {
    const double st = std::sin(q[1]), ct = std::cos(q[1]);
    const double sp = std::sin(q[2]), cp = std::cos(q[2]);
    const Vec3 dirs[3] = {{st * cp, st * sp, ct}, {ct * cp, ct * sp, -st}, {-sp, cp, 0}};
    d = dirs[axis];
  } else if (kind == GridKind3D::cylindrical) {
    const double sa = std::sin(q[1]), ca = std::cos(q[1]);
    const Vec3 dirs[3] = {{ca, sa, 0}, {-sa, ca, 0}, {0, 0, 1}};
    d = dirs[axis];
  }
  return placement.rotation * d;
}

GridDecomposition3D decompose_geometry_3d(const Geometry3D& geo) {
  validate_outer(geo);
  const double len_tol = 1e-9 * domain_length(geo);
  GridDecomposition3D dec;
  dec.frames.resize(1);
  dec.frames[0].kind = GridKind3D::spherical;
  dec.frames[0].periodic = {false, false, true};
  std::vector<std::vector<GridRanges>> ranges(1);
  dec.part_frame.resize(geo.parts.size());

  for (std::size_t p = 0; p < geo.parts.size(); ++p) {
    const Part3D& part = geo.parts[p];
    validate_placement(part);
    // A triangulated surface is no grid's: the mesher takes its triangles as they are.
    if (std::holds_alternative<TriangleSurface>(part.shape)) {
      dec.part_frame[p] = -1;
      continue;
    }
    std::visit([&](const auto& s) { validate_shape(part, s); }, part.shape);
    validate_thickness(geo, part);
    const GridKind3D kind = kind_of(part.shape);
    Vec3 off = Vec3::Zero();
    std::size_t f = 0;
    for (; f < dec.frames.size(); ++f)
      if (dec.frames[f].kind == kind && frame_offset(dec.frames[f], part.placement, len_tol, off))
        break;
    if (f == dec.frames.size()) {
      GridFrame3D nf;
      nf.kind = kind;
      nf.placement = part.placement;
      nf.periodic = {false, kind == GridKind3D::cylindrical, kind == GridKind3D::spherical};
      dec.frames.push_back(nf);
      ranges.emplace_back();
      off = Vec3::Zero();
    }
    dec.frames[f].parts.push_back(static_cast<int>(p));
    ranges[f].push_back(ranges_in_frame(part, off));
    dec.part_frame[p] = static_cast<int>(f);
  }

  const double r1 = geo.outer.radius;
  for (std::size_t f = 0; f < dec.frames.size(); ++f) {
    GridFrame3D& fr = dec.frames[f];
    validate_radial_gaps(geo, fr, ranges[f], len_tol);
    ExtraBreaks extra;
    if (f == 0) {
      extra[0].push_back(r1);
      if (geo.outer.kind == OuterKind3D::open)
        extra[0].push_back(geo.outer.shell_ratio * r1);
    }
    // A frame that cannot follow a plane is fine as long as its parts keep off the plane
    // (clip_faces checks).
    for (const SymmetryPlane3D& p : geo.symmetry)
      add_plane_breaks(fr, p, len_tol, extra);
    set_breaks(fr, ranges[f], len_tol, extra);
    label_cells(fr, geo, ranges[f]);
    if (f == 0)
      label_outer(fr, geo);
    collect_faces(fr, static_cast<int>(f), dec.faces);
  }
  clip_faces(geo, dec, 1e-7 * domain_length(geo));
  return dec;
}

bool part_contains(const Part3D& part, const Vec3& x, double tol) {
  const Vec3 l = part.placement.to_local(x);
  if (const auto* s = std::get_if<SphericalSegment>(&part.shape)) {
    const double r = l.norm();
    if (r < s->r_inner - tol || r > s->r_outer + tol)
      return false;
    if (r <= tol)
      return s->r_inner <= tol;
    const double theta = std::acos(std::clamp(l.z() / r, -1.0, 1.0));
    const double ang_tol = tol / r;
    if (theta < s->theta_min - ang_tol || theta > s->theta_max + ang_tol)
      return false;
    const double rho = l.head<2>().norm();
    if (s->phi_max - s->phi_min >= two_pi - angle_tol || rho <= tol)
      return true;
    const double phi = std::atan2(l.y(), l.x());
    const double mid = 0.5 * (s->phi_min + s->phi_max);
    const double d = std::abs(std::remainder(phi - mid, two_pi));
    return d <= 0.5 * (s->phi_max - s->phi_min) + tol / rho;
  }
  if (const auto* c = std::get_if<Cylinder>(&part.shape)) {
    const double rho = l.head<2>().norm();
    return l.z() >= -tol && l.z() <= c->height + tol && rho >= c->r_inner - tol &&
           rho <= c->r_outer + tol;
  }
  if (const auto* t = std::get_if<TriangleSurface>(&part.shape))
    return t->index->contains(l, tol);
  const Vec3 h = std::get<Box>(part.shape).size / 2;
  return (l.cwiseAbs() - h).maxCoeff() <= tol;
}

} // namespace magfem
