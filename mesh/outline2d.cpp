#include "mesh/outline2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/constants.hpp"
#include "mesh/mesh_error.hpp"

namespace magfem {

namespace {

constexpr double two_pi = 2.0 * pi;
constexpr int min_chords_per_turn = 8;
// A curve needing more pieces than this means a tolerance or size far below the geometry.
constexpr int max_pieces_per_curve = 1'000'000;
constexpr double full_turn_rel_tol = 1e-12; // relative slack for "the span is a full turn"

double wrap_angle(double a) {
  a = std::fmod(a, two_pi);
  return a < 0 ? a + two_pi : a;
}

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

bool finite(const Vec2& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y());
}

bool positive(double v) {
  return v > 0 && std::isfinite(v);
}

// Smallest chord limit along a curve given as t in [0, 1] -> point. Sampling is refined until
// the sample spacing is at most half the smallest limit seen, so a narrow dip of the limit
// (a thin gap facing the curve) is not stepped over.
double min_limit_along(const std::function<Vec2(double)>& at, double length,
                       const ChordLimit2D& limit) {
  int m = 16;
  double h = std::numeric_limits<double>::infinity();
  for (int round = 0; round < 4; ++round) {
    for (int k = 0; k <= m; ++k)
      h = std::min(h, limit(at(double(k) / m)));
    if (!(h > 0))
      return h;
    if (length / m <= 0.5 * h)
      break;
    m = int(std::min(double(max_pieces_per_curve), std::ceil(2.0 * length / h)));
  }
  return h;
}

double shoelace(const std::vector<Vec2>& loop) {
  double a = 0;
  for (std::size_t i = 0, n = loop.size(); i < n; ++i)
    a += cross(loop[i], loop[(i + 1) % n]);
  return 0.5 * a;
}

int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double o = cross(b - a, c - a);
  return (o > 0) - (o < 0);
}

bool on_segment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// Closed segments ab and cd share at least one point.
bool segments_touch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4)
    return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

bool lexicographically_less(const Vec2& a, const Vec2& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

std::vector<Vec2> rectangle_corners(const Rectangle& r) {
  const Eigen::Rotation2Dd rot(r.rotation);
  const double hw = 0.5 * r.width, hh = 0.5 * r.height;
  return {r.center + rot * Vec2(-hw, -hh), r.center + rot * Vec2(hw, -hh),
          r.center + rot * Vec2(hw, hh), r.center + rot * Vec2(-hw, hh)};
}

} // namespace

// ---- phase 1: validation and arc requests ----------------------------------------------------

OutlineBuilder2D::OutlineBuilder2D(const Part2D& part, double chord_tolerance, ChordLimit2D limit,
                                   CircleSet2D& circles)
    : part_(part), tol_(chord_tolerance), limit_(std::move(limit)) {
  if (!positive(tol_))
    throw MeshError("", "chord_tolerance", "must be a finite length > 0");
  if (!(part.max_size >= 0) || !std::isfinite(part.max_size))
    fail("max_size", "must be a finite size >= 0 (0 = default size)");
  if (const auto* d = std::get_if<Disk>(&part.shape)) {
    check_center(d->center);
    if (!positive(d->radius))
      fail("radius", "must be a finite radius > 0");
    outer_arc_ = request_arc(circles, d->center, d->radius, 0.0, two_pi);
  } else if (const auto* a = std::get_if<Annulus>(&part.shape)) {
    check_center(a->center);
    check_radii(a->r_inner, a->r_outer);
    outer_arc_ = request_arc(circles, a->center, a->r_outer, 0.0, two_pi);
    if (a->r_inner > 0)
      inner_arc_ = request_arc(circles, a->center, a->r_inner, 0.0, two_pi);
  } else if (const auto* s = std::get_if<AnnularSector>(&part.shape)) {
    check_center(s->center);
    check_radii(s->r_inner, s->r_outer);
    const double span = s->angle_end - s->angle_start;
    if (!std::isfinite(span) || !(span > 0))
      fail("angle_end", "must exceed angle_start (angles counter-clockwise)");
    if (span > two_pi * (1 + full_turn_rel_tol))
      fail("angle_end", "the span exceeds a full turn");
    const double a0 = span >= two_pi * (1 - full_turn_rel_tol) ? 0.0 : s->angle_start;
    outer_arc_ = request_arc(circles, s->center, s->r_outer, a0, span);
    if (s->r_inner > 0)
      inner_arc_ = request_arc(circles, s->center, s->r_inner, a0, span);
  } else if (const auto* r = std::get_if<Rectangle>(&part.shape)) {
    check_center(r->center);
    if (!positive(r->width))
      fail("width", "must be a finite width > 0");
    if (!positive(r->height))
      fail("height", "must be a finite height > 0");
    if (!std::isfinite(r->rotation))
      fail("rotation", "must be finite");
  } else {
    const auto& v = std::get<Polygon>(part.shape).vertices;
    if (v.size() < 3)
      fail("vertices", "a polygon needs at least 3 vertices");
    for (const Vec2& x : v)
      if (!finite(x))
        fail("vertices", "vertices must be finite");
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n; ++i)
      if (v[i] == v[(i + 1) % n])
        fail("vertices", "repeated vertex " + std::to_string(i + 1));
    if (std::abs(shoelace(v)) <= 1e-14 * (v[0] - v[1]).squaredNorm() * double(n))
      fail("vertices", "the polygon has zero area");
    check_simple(v);
  }
}

void OutlineBuilder2D::fail(const std::string& field, const std::string& msg) const {
  throw MeshError(part_.name, field, msg);
}

void OutlineBuilder2D::check_center(const Vec2& c) const {
  if (!finite(c))
    fail("center", "must be finite");
}

void OutlineBuilder2D::check_radii(double r_inner, double r_outer) const {
  if (!positive(r_outer))
    fail("r_outer", "must be a finite radius > 0");
  if (!(r_inner >= 0) || !(r_inner < r_outer))
    fail("r_inner", "must satisfy 0 <= r_inner < r_outer");
}

void OutlineBuilder2D::check_simple(const std::vector<Vec2>& v) const {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = v[i], &b = v[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec2 &c = v[j], &d = v[(j + 1) % n];
      const bool next = j == i + 1, prev = (j + 1) % n == i;
      const std::string edges = std::to_string(i + 1) + " and " + std::to_string(j + 1);
      if (next || prev) {
        // Adjacent edges share a vertex; they must not fold back onto each other.
        const Vec2& shared = next ? b : a;
        const Vec2& p = next ? a : b;
        const Vec2& q = next ? d : c;
        if (orientation(p, shared, q) == 0 && (p - shared).dot(q - shared) > 0)
          fail("vertices", "edges " + edges + " overlap");
        continue;
      }
      if (segments_touch(a, b, c, d))
        fail("vertices", "the polygon intersects itself (edges " + edges + ")");
    }
  }
}

int OutlineBuilder2D::request_arc(CircleSet2D& circles, const Vec2& c, double r, double a0,
                                  double span) const {
  const double sagitta_angle = 2.0 * std::acos(std::max(-1.0, 1.0 - tol_ / r));
  const auto at = [&](double t) {
    return Vec2(c + r * Vec2(std::cos(a0 + t * span), std::sin(a0 + t * span)));
  };
  const double h = min_limit_along(at, r * span, limit_);
  const double size_angle = h >= 2 * r ? pi : 2.0 * std::asin(h / (2 * r));
  const double angle = std::min({sagitta_angle, size_angle, two_pi / min_chords_per_turn});
  if (!(angle * max_pieces_per_curve >= two_pi))
    fail("", "a circle of radius " + std::to_string(r) +
                 " m needs more than a million chords (size or chord tolerance too small)");
  return circles.request(c, r, a0, span, angle);
}

// ---- phase 2: loops --------------------------------------------------------------------------

// Appends the interior split points of segment ab and then b, unless b closes the loop. The
// points are computed from the lexicographically smaller end so that they do not depend on the
// direction in which the edge is walked.
void OutlineBuilder2D::append_segment(std::vector<Vec2>& loop, Vec2 a, Vec2 b) const {
  const bool flip = lexicographically_less(b, a);
  const Vec2 p = flip ? b : a, q = flip ? a : b;
  const double len = (q - p).norm();
  const auto at = [&](double t) { return Vec2(p + t * (q - p)); };
  const double h = min_limit_along(at, len, limit_);
  const double n = std::max(1.0, std::ceil(len / h));
  if (!(n <= max_pieces_per_curve))
    fail("", "an edge needs more than a million pieces");
  std::vector<Vec2> inner;
  for (int k = 1; k < int(n); ++k)
    inner.push_back(at(double(k) / n));
  if (flip)
    std::reverse(inner.begin(), inner.end());
  loop.insert(loop.end(), inner.begin(), inner.end());
  if (!loop.empty() && b == loop.front())
    return;
  loop.push_back(b);
}

std::vector<Vec2> OutlineBuilder2D::close_polyline(const std::vector<Vec2>& corners) const {
  std::vector<Vec2> loop{corners.front()};
  for (std::size_t i = 0; i < corners.size(); ++i)
    append_segment(loop, corners[i], corners[(i + 1) % corners.size()]);
  return loop;
}

void OutlineBuilder2D::add_arcs(Outline2D& o, const CircleSet2D& circles) const {
  o.outer_circle_ = circles.circle_of(outer_arc_);
  o.max_sagitta_ = circles.max_sagitta(o.outer_circle_);
  if (inner_arc_ >= 0) {
    o.inner_circle_ = circles.circle_of(inner_arc_);
    o.max_sagitta_ = std::max(o.max_sagitta_, circles.max_sagitta(o.inner_circle_));
  }
  const auto* s = std::get_if<AnnularSector>(&part_.shape);
  const double span = s ? s->angle_end - s->angle_start : two_pi;
  if (span >= two_pi * (1 - full_turn_rel_tol)) { // full disk or ring
    o.loops_.push_back(circles.arc_points(outer_arc_));
    if (inner_arc_ >= 0)
      o.loops_.push_back(circles.arc_points(inner_arc_));
    return;
  }
  o.sector_ = true;
  o.sector_center_ = s->center;
  o.sector_start_ = s->angle_start;
  o.sector_span_ = span;
  std::vector<Vec2> loop = circles.arc_points(outer_arc_);
  const Vec2 outer_start = loop.front();
  if (inner_arc_ >= 0) {
    std::vector<Vec2> inner = circles.arc_points(inner_arc_);
    append_segment(loop, loop.back(), inner.back());
    loop.insert(loop.end(), inner.rbegin() + 1, inner.rend());
  } else {
    append_segment(loop, loop.back(), s->center);
  }
  append_segment(loop, loop.back(), outer_start);
  o.loops_.push_back(std::move(loop));
}

Outline2D OutlineBuilder2D::build(const std::shared_ptr<const CircleSet2D>& circles) const {
  Outline2D o;
  o.shape_ = part_.shape;
  o.circles_ = circles;
  if (outer_arc_ >= 0) {
    add_arcs(o, *circles);
  } else if (const auto* r = std::get_if<Rectangle>(&part_.shape)) {
    o.loops_.push_back(close_polyline(rectangle_corners(*r)));
  } else {
    o.loops_.push_back(close_polyline(std::get<Polygon>(part_.shape).vertices));
  }
  o.lo_ = o.hi_ = o.loops_.front().front();
  for (const auto& loop : o.loops_)
    for (const Vec2& v : loop) {
      o.lo_ = o.lo_.cwiseMin(v);
      o.hi_ = o.hi_.cwiseMax(v);
    }
  if (const auto* poly = std::get_if<Polygon>(&part_.shape))
    bin_edges(o, poly->vertices);
  return o;
}

// Horizontal bands of the bounding box, each listing the polygon edges that overlap it, so that
// a containment query visits a few edges instead of all.
void OutlineBuilder2D::bin_edges(Outline2D& o, const std::vector<Vec2>& v) {
  const std::size_t n_bands = std::max<std::size_t>(1, v.size() / 4);
  o.edge_bands_.assign(n_bands, {});
  const double y0 = o.lo_.y(), dy = (o.hi_.y() - o.lo_.y()) / double(n_bands);
  const auto band = [&](double y) {
    return std::min(n_bands - 1, std::size_t(std::max(0.0, (y - y0) / dy)));
  };
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 &a = v[i], &b = v[(i + 1) % v.size()];
    for (std::size_t k = band(std::min(a.y(), b.y())); k <= band(std::max(a.y(), b.y())); ++k)
      o.edge_bands_[k].push_back(int(i));
  }
}

// ---- queries ---------------------------------------------------------------------------------

bool Outline2D::contains(const Vec2& p) const {
  if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any())
    return false;
  if (const auto* r = std::get_if<Rectangle>(&shape_)) {
    const Vec2 q = Eigen::Rotation2Dd(-r->rotation) * (p - r->center);
    return std::abs(q.x()) < 0.5 * r->width && std::abs(q.y()) < 0.5 * r->height;
  }
  if (const auto* poly = std::get_if<Polygon>(&shape_)) {
    // Crossing number on the original vertices, over the edges of p's horizontal band only.
    const auto& v = poly->vertices;
    const std::size_t band =
        std::min(edge_bands_.size() - 1,
                 std::size_t((p.y() - lo_.y()) / (hi_.y() - lo_.y()) * double(edge_bands_.size())));
    bool inside = false;
    for (const int i : edge_bands_[band]) {
      const Vec2 &a = v[std::size_t(i)], &b = v[(std::size_t(i) + 1) % v.size()];
      if ((a.y() > p.y()) != (b.y() > p.y()) &&
          p.x() < b.x() + (p.y() - b.y()) * (a.x() - b.x()) / (a.y() - b.y()))
        inside = !inside;
    }
    return inside;
  }
  if (sector_) {
    const Vec2 d = p - sector_center_;
    if (wrap_angle(std::atan2(d.y(), d.x()) - sector_start_) >= sector_span_)
      return false;
  }
  if (!circles_->inside(outer_circle_, p))
    return false;
  return inner_circle_ < 0 || !circles_->inside(inner_circle_, p);
}

double Outline2D::polygon_area() const {
  double a = std::abs(shoelace(loops_.front()));
  for (std::size_t i = 1; i < loops_.size(); ++i)
    a -= std::abs(shoelace(loops_[i]));
  return a;
}

double Outline2D::exact_area() const {
  struct Area {
    double operator()(const Disk& d) const { return pi * d.radius * d.radius; }
    double operator()(const Annulus& a) const {
      return pi * (a.r_outer * a.r_outer - a.r_inner * a.r_inner);
    }
    double operator()(const AnnularSector& s) const {
      return 0.5 * (s.angle_end - s.angle_start) * (s.r_outer * s.r_outer - s.r_inner * s.r_inner);
    }
    double operator()(const Rectangle& r) const { return r.width * r.height; }
    double operator()(const Polygon& p) const { return std::abs(shoelace(p.vertices)); }
  };
  return std::visit(Area{}, shape_);
}

} // namespace magfem
