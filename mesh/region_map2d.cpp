#include "mesh/region_map2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "core/constants.hpp"
#include "mesh/mesh_error.hpp"

namespace magfem {

namespace {

constexpr int min_shell_layers = 4;
// The outer circles get at least this many chords: the mesher moves the vertices CGAL adds on
// their chords onto the circle, which tilts the triangles there by about a quarter of the
// chord angle (< 0.7 degrees here, within the 1 degree margin asked of CGAL).
constexpr int min_outer_chords = 128;
// No triangle has all angles above 60 degrees.
constexpr double max_min_angle_deg = 60.0;

bool positive(double v) {
  return v > 0 && std::isfinite(v);
}

// The domain (r_inner = 0) or the shell: the disk of r_outer about the origin (region_of()
// tests the domain first), or the x >= 0 half of the ring, so that the straight sides of the
// shell and of the domain do not overlap.
// With symmetry planes, the quarter or half of the disk on their kept side (mesh/
// symmetry_plane2d.hpp); the axisymmetric half plane keeps x >= 0 anyway.
Shape2D outer_shape(const Geometry2D& g, double r_inner, double r_outer) {
  bool keep_x = g.symmetry == Symmetry2D::axisymmetric, keep_y = false;
  for (const SymmetryPlane2D& p : g.planes)
    (p.axis == 0 ? keep_x : keep_y) = true;
  if (keep_x && keep_y)
    return AnnularSector{Vec2::Zero(), r_inner, r_outer, 0.0, 0.5 * pi};
  if (keep_x)
    return AnnularSector{Vec2::Zero(), r_inner, r_outer, -0.5 * pi, 0.5 * pi};
  if (keep_y)
    return AnnularSector{Vec2::Zero(), r_inner, r_outer, 0.0, pi};
  return Disk{Vec2::Zero(), r_outer};
}

// A point on the cut side of a symmetry plane (the sector's radial edges: their far ends come
// out of cos(pi/2) a hair off the plane).
bool on_plane(const Geometry2D& g, const Vec2& x) {
  for (const SymmetryPlane2D& p : g.planes)
    if (std::abs(x[p.axis]) <= 1e-12 * g.outer.radius)
      return true;
  return false;
}

} // namespace

RegionMap2D::RegionMap2D(const Geometry2D& g, const Limit& limit, double shell_size) {
  validate(g);
  const MeshOptions2D& o = g.options;
  background_size_ = o.default_size * o.size_scale;
  for (const Part2D& p : g.parts)
    part_sizes_.push_back((p.max_size > 0 ? p.max_size : o.default_size) * o.size_scale);
  // Phase 1: every outline requests its arcs, so that circles shared by parts are cut once.
  auto circles = std::make_shared<CircleSet2D>();
  const auto limit_of = [&limit](int region) {
    return [&limit, region](const Vec2& x) { return limit(region, x); };
  };
  // Scaled with size_scale like every size, so that refinement studies stay uniform. The axis
  // sides of a half disk, and the cut sides of symmetry planes, are not split here: CGAL splits
  // them where the refinement needs it and at the vertices parts put on the axis, which a fixed
  // split would miss by a hair.
  const bool axi = g.symmetry == Symmetry2D::axisymmetric;
  const auto outer_limit = [&limit, &o, &g, axi](int region, double r) {
    const double longest = 2.0 * pi * r / min_outer_chords * std::min(1.0, o.size_scale);
    return [&limit, &g, region, longest, axi](const Vec2& x) {
      if ((axi && x.x() == 0) || on_plane(g, x))
        return std::numeric_limits<double>::infinity();
      return std::min(longest, limit(region, x));
    };
  };
  std::vector<OutlineBuilder2D> builders;
  for (std::size_t i = 0; i < g.parts.size(); ++i)
    builders.emplace_back(g.parts[i], o.chord_tolerance, limit_of(int(i)), *circles);
  const double r1 = g.outer.radius, r2 = g.outer.shell_ratio * r1;
  const bool open = g.outer.kind == OuterKind::open;
  builders.emplace_back(Part2D{"", outer_shape(g, 0, r1), 0}, o.chord_tolerance,
                        outer_limit(region_background, r1), *circles);
  if (open)
    builders.emplace_back(Part2D{"", outer_shape(g, r1, r2), 0}, o.chord_tolerance,
                          outer_limit(region_shell, r2), *circles);
  circles->finalize();
  // Phase 2: loops on the shared circles.
  for (std::size_t i = 0; i < g.parts.size(); ++i)
    parts_.push_back(builders[i].build(circles));
  domain_ = builders[g.parts.size()].build(circles);
  check_inside_domain(g);
  if (!open)
    return;
  const auto& loop = domain_->loops().front();
  double chord = 0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    chord = std::max(chord, (loop[(i + 1) % loop.size()] - loop[i]).norm());
  shell_size_ = shell_size > 0
                    ? shell_size
                    : std::min(chord, (r2 - r1) / min_shell_layers * std::min(1.0, o.size_scale));
  shell_ = builders.back().build(circles);
}

void RegionMap2D::validate(const Geometry2D& g) const {
  const MeshOptions2D& o = g.options;
  if (!positive(o.default_size))
    throw MeshError("", "default_size", "must be a length > 0");
  if (!positive(o.chord_tolerance))
    throw MeshError("", "chord_tolerance", "must be a length > 0");
  if (!(o.min_angle_deg > 0 && o.min_angle_deg < max_min_angle_deg))
    throw MeshError("", "min_angle_deg", "must lie in (0, 60) degrees");
  if (o.gap_layers < 1)
    throw MeshError("", "gap_layers", "must be at least 1");
  if (!positive(o.size_scale))
    throw MeshError("", "size_scale", "must be > 0");
  if (!positive(g.outer.radius))
    throw MeshError("", "radius", "the outer radius must be > 0");
  if (g.outer.kind == OuterKind::open &&
      !(g.outer.shell_ratio > 1 && std::isfinite(g.outer.shell_ratio)))
    throw MeshError("", "shell_ratio", "must be > 1 for an open boundary");
}

void RegionMap2D::check_inside_domain(const Geometry2D& g) const {
  // Vertices on the domain polygon itself are accepted (pulled inwards by a relative 1e-9).
  // On the axis of a half disk they are pushed off it by as much.
  constexpr double inward = 1.0 - 1e-9;
  const double off_axis = g.symmetry == Symmetry2D::axisymmetric ? 1e-9 * g.outer.radius : 0.0;
  // A part crossing a symmetry plane is cut there: its vertices beyond are tested at their
  // mirror images, off the plane by as much.
  const auto folded = [&](const Vec2& v) {
    Vec2 w = inward * v + Vec2(off_axis, 0);
    for (const SymmetryPlane2D& p : g.planes)
      w[p.axis] = std::abs(w[p.axis]) + 1e-9 * g.outer.radius;
    return w;
  };
  for (std::size_t i = 0; i < parts_.size(); ++i)
    for (const auto& loop : parts_[i].loops())
      for (const Vec2& v : loop)
        if (!domain_->contains(folded(v)))
          throw MeshError(g.parts[i].name, "",
                          "the part reaches beyond the domain boundary (radius " +
                              std::to_string(g.outer.radius) + " m" +
                              (off_axis > 0 ? ", r >= 0" : "") + "): enlarge the outer radius");
}

int RegionMap2D::region_of(const Vec2& p) const {
  if (!domain_->contains(p))
    return shell_ && shell_->contains(p) ? region_shell : region_outside;
  for (std::size_t i = parts_.size(); i-- > 0;)
    if (parts_[i].contains(p))
      return int(i);
  return region_background;
}

double RegionMap2D::size_of(int region) const {
  if (region >= 0)
    return part_sizes_[std::size_t(region)];
  if (region == region_background)
    return background_size_;
  if (region == region_shell)
    return shell_size_;
  return std::numeric_limits<double>::infinity();
}

double RegionMap2D::max_sagitta() const {
  double s = domain_->max_sagitta();
  if (shell_)
    s = std::max(s, shell_->max_sagitta());
  for (const auto& p : parts_)
    s = std::max(s, p.max_sagitta());
  return s;
}

} // namespace magfem
