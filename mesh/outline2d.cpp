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
// Relative slack for "the span is a full turn".
constexpr double full_turn_rel_tol = 1e-12;

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

} // namespace

// Validates one part and fills an Outline2D; one member function per primitive.
class OutlineBuilder2D {
public:
  OutlineBuilder2D(const Part2D& part, double tol, const ChordLimit2D& limit)
      : part_(part), tol_(tol), limit_(limit) {}

  Outline2D build() {
    if (!(part_.max_size >= 0) || !std::isfinite(part_.max_size))
      fail("max_size", "must be a finite size >= 0 (0 = default size)");
    out_.shape_ = part_.shape;
    std::visit([this](const auto& s) { add(s); }, part_.shape);
    finish();
    return std::move(out_);
  }

private:
  [[noreturn]] void fail(const std::string& field, const std::string& msg) const {
    throw MeshError(part_.name, field, msg);
  }

  void check_center(const Vec2& c) const {
    if (!finite(c))
      fail("center", "must be finite");
  }

  void check_radii(double r_inner, double r_outer) const {
    if (!(r_outer > 0) || !std::isfinite(r_outer))
      fail("r_outer", "must be a finite radius > 0");
    if (!(r_inner >= 0) || !(r_inner < r_outer))
      fail("r_inner", "must satisfy 0 <= r_inner < r_outer");
  }

  void add(const Disk& d) {
    check_center(d.center);
    if (!(d.radius > 0) || !std::isfinite(d.radius))
      fail("radius", "must be a finite radius > 0");
    add_rings(d.center, 0.0, d.radius, 0.0);
  }

  void add(const Annulus& a) {
    check_center(a.center);
    check_radii(a.r_inner, a.r_outer);
    add_rings(a.center, a.r_inner, a.r_outer, 0.0);
  }

  void add(const AnnularSector& s) {
    check_center(s.center);
    check_radii(s.r_inner, s.r_outer);
    const double span = s.angle_end - s.angle_start;
    if (!std::isfinite(span) || !(span > 0))
      fail("angle_end", "must exceed angle_start (angles counter-clockwise)");
    if (span > two_pi * (1 + full_turn_rel_tol))
      fail("angle_end", "the span exceeds a full turn");
    if (span >= two_pi * (1 - full_turn_rel_tol)) {
      add_rings(s.center, s.r_inner, s.r_outer, s.angle_start); // a full ring, no radial edges
      return;
    }
    kind_sector_ = true;
    const Outline2D::Arc outer = make_arc(s.center, s.r_outer, s.angle_start, span);
    std::vector<Vec2> loop;
    append_arc(loop, outer, false);
    if (s.r_inner > 0) {
      const Outline2D::Arc inner = make_arc(s.center, s.r_inner, s.angle_start, span);
      append_segment(loop, loop.back(), arc_point(inner, inner.n_chords));
      append_arc(loop, inner, true);
      append_segment(loop, loop.back(), loop.front());
      out_.arcs_ = {outer, inner};
    } else {
      append_segment(loop, loop.back(), s.center);
      append_segment(loop, s.center, loop.front());
      out_.arcs_ = {outer};
    }
    out_.loops_.push_back(std::move(loop));
  }

  void add(const Rectangle& r) {
    check_center(r.center);
    if (!(r.width > 0) || !std::isfinite(r.width))
      fail("width", "must be a finite width > 0");
    if (!(r.height > 0) || !std::isfinite(r.height))
      fail("height", "must be a finite height > 0");
    if (!std::isfinite(r.rotation))
      fail("rotation", "must be finite");
    const Eigen::Rotation2Dd rot(r.rotation);
    const double hw = 0.5 * r.width, hh = 0.5 * r.height;
    close_polyline({r.center + rot * Vec2(-hw, -hh), r.center + rot * Vec2(hw, -hh),
                    r.center + rot * Vec2(hw, hh), r.center + rot * Vec2(-hw, hh)});
  }

  void add(const Polygon& p) {
    const auto& v = p.vertices;
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
    close_polyline(v);
  }

  void check_simple(const std::vector<Vec2>& v) const {
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 &a = v[i], &b = v[(i + 1) % n];
      for (std::size_t j = i + 1; j < n; ++j) {
        const Vec2 &c = v[j], &d = v[(j + 1) % n];
        const bool next = j == i + 1, prev = (j + 1) % n == i;
        if (next || prev) {
          // Adjacent edges share a vertex; they must not fold back onto each other.
          const Vec2& shared = next ? b : a;
          const Vec2& p = next ? a : b;
          const Vec2& q = next ? d : c;
          if (orientation(p, shared, q) == 0 && (p - shared).dot(q - shared) > 0)
            fail("vertices",
                 "edges " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + " overlap");
          continue;
        }
        if (segments_touch(a, b, c, d))
          fail("vertices", "the polygon intersects itself (edges " + std::to_string(i + 1) +
                               " and " + std::to_string(j + 1) + ")");
      }
    }
  }

  // Full circle (r_inner = 0) or full ring about c, chords starting at angle a0.
  void add_rings(const Vec2& c, double r_inner, double r_outer, double a0) {
    const Outline2D::Arc outer = make_arc(c, r_outer, a0, two_pi);
    out_.arcs_.push_back(outer);
    out_.loops_.push_back(full_loop(outer));
    if (r_inner > 0) {
      const Outline2D::Arc inner = make_arc(c, r_inner, a0, two_pi);
      out_.arcs_.push_back(inner);
      out_.loops_.push_back(full_loop(inner));
    }
  }

  Outline2D::Arc make_arc(const Vec2& c, double r, double a0, double span) {
    Outline2D::Arc arc{c, r, a0, span, 0};
    const double half_angle = std::acos(std::max(-1.0, 1.0 - tol_ / r));
    const double n_sagitta = std::ceil(span / (2.0 * half_angle));
    const double n_turn = std::ceil(min_chords_per_turn * span / two_pi - 1e-9);
    const auto at = [&](double t) {
      return Vec2(c + r * Vec2(std::cos(a0 + t * span), std::sin(a0 + t * span)));
    };
    const double h = min_limit_along(at, r * span, limit_);
    const double n_size = std::ceil(r * span / h);
    const double n = std::max({1.0, n_sagitta, n_turn, n_size});
    if (!(n <= max_pieces_per_curve))
      fail("", "an arc of radius " + std::to_string(r) +
                   " m needs more than a million chords (size or chord tolerance too small)");
    arc.n_chords = int(n);
    out_.max_sagitta_ = std::max(out_.max_sagitta_, r * (1 - std::cos(0.5 * span / n)));
    return arc;
  }

  static Vec2 arc_point(const Outline2D::Arc& a, int k) {
    const double phi = a.angle_start + a.span * k / a.n_chords;
    return a.center + a.radius * Vec2(std::cos(phi), std::sin(phi));
  }

  static std::vector<Vec2> full_loop(const Outline2D::Arc& a) {
    std::vector<Vec2> loop;
    for (int k = 0; k < a.n_chords; ++k)
      loop.push_back(arc_point(a, k));
    return loop;
  }

  // Appends the arc's vertices 0..n (or n..0 when reversed), skipping one equal to the last.
  static void append_arc(std::vector<Vec2>& loop, const Outline2D::Arc& a, bool reversed) {
    for (int k = 0; k <= a.n_chords; ++k) {
      const Vec2 v = arc_point(a, reversed ? a.n_chords - k : k);
      if (loop.empty() || v != loop.back())
        loop.push_back(v);
    }
  }

  // Appends the interior split points of segment ab and then b, unless b closes the loop.
  void append_segment(std::vector<Vec2>& loop, const Vec2 a, const Vec2 b) {
    const double len = (b - a).norm();
    const auto at = [&](double t) { return Vec2(a + t * (b - a)); };
    const double h = min_limit_along(at, len, limit_);
    const double n = std::max(1.0, std::ceil(len / h));
    if (!(n <= max_pieces_per_curve))
      fail("", "an edge needs more than a million pieces (size too small)");
    for (int k = 1; k < int(n); ++k)
      loop.push_back(at(double(k) / n));
    if (!loop.empty() && b == loop.front())
      return;
    loop.push_back(b);
  }

  void close_polyline(const std::vector<Vec2>& corners) {
    std::vector<Vec2> loop{corners.front()};
    for (std::size_t i = 0; i < corners.size(); ++i)
      append_segment(loop, corners[i], corners[(i + 1) % corners.size()]);
    out_.loops_.push_back(std::move(loop));
  }

  void finish() {
    out_.kind_sector_ = kind_sector_;
    out_.lo_ = out_.hi_ = out_.loops_.front().front();
    for (const auto& loop : out_.loops_)
      for (const Vec2& v : loop) {
        out_.lo_ = out_.lo_.cwiseMin(v);
        out_.hi_ = out_.hi_.cwiseMax(v);
      }
  }

  const Part2D& part_;
  double tol_;
  const ChordLimit2D& limit_;
  bool kind_sector_ = false;
  Outline2D out_;
};

Outline2D Outline2D::build(const Part2D& part, double chord_tolerance, const ChordLimit2D& limit) {
  if (!(chord_tolerance > 0) || !std::isfinite(chord_tolerance))
    throw MeshError("", "chord_tolerance", "must be a finite length > 0");
  return OutlineBuilder2D(part, chord_tolerance, limit).build();
}

bool Outline2D::inside_arc_chain(const Vec2& p, const Arc& arc) const {
  const Vec2 d = p - arc.center;
  const double t = wrap_angle(std::atan2(d.y(), d.x()) - arc.angle_start);
  const double dphi = arc.span / arc.n_chords;
  const int k = std::clamp(int(t / dphi), 0, arc.n_chords - 1);
  const double mid = arc.angle_start + (k + 0.5) * dphi;
  return d.x() * std::cos(mid) + d.y() * std::sin(mid) < arc.radius * std::cos(0.5 * dphi);
}

bool Outline2D::contains(const Vec2& p) const {
  if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any())
    return false;
  if (const auto* r = std::get_if<Rectangle>(&shape_)) {
    const Vec2 q = Eigen::Rotation2Dd(-r->rotation) * (p - r->center);
    return std::abs(q.x()) < 0.5 * r->width && std::abs(q.y()) < 0.5 * r->height;
  }
  if (const auto* poly = std::get_if<Polygon>(&shape_)) {
    bool inside = false; // crossing number on the original vertices
    const auto& v = poly->vertices;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      if ((v[i].y() > p.y()) != (v[j].y() > p.y()) &&
          p.x() < v[j].x() + (p.y() - v[j].y()) * (v[i].x() - v[j].x()) / (v[i].y() - v[j].y()))
        inside = !inside;
    }
    return inside;
  }
  if (kind_sector_) {
    const Arc& outer = arcs_.front();
    const Vec2 d = p - outer.center;
    if (wrap_angle(std::atan2(d.y(), d.x()) - outer.angle_start) >= outer.span)
      return false;
  }
  if (!inside_arc_chain(p, arcs_.front()))
    return false;
  return arcs_.size() < 2 || !inside_arc_chain(p, arcs_[1]);
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
