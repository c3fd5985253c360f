#include "mesh/circle_set2d.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace magfem {

namespace {

constexpr double two_pi = 2.0 * pi;
constexpr double same_circle_rel_tol = 1e-12;
constexpr double same_angle_tol = 1e-9; // radians: corners closer than this coincide
constexpr double corner_grid_shrink = 2.0 / 3.0;
constexpr double full_turn_rel_tol = 1e-12;

double wrap_angle(double a) {
  a = std::fmod(a, two_pi);
  if (a < 0)
    a += two_pi;
  return a >= two_pi ? 0.0 : a;
}

bool full_turn(double span) {
  return span >= two_pi * (1 - full_turn_rel_tol);
}

} // namespace

int CircleSet2D::find_or_add(const Vec2& center, double radius) {
  for (std::size_t i = 0; i < circles_.size(); ++i) {
    const Circle& c = circles_[i];
    if ((c.center - center).norm() <= same_circle_rel_tol * radius &&
        std::abs(c.radius - radius) <= same_circle_rel_tol * radius)
      return int(i);
  }
  circles_.push_back({center, radius, two_pi, false, {}, {}});
  return int(circles_.size() - 1);
}

int CircleSet2D::request(const Vec2& center, double radius, double angle_start, double span,
                         double max_chord_angle) {
  const int c = find_or_add(center, radius);
  Circle& circle = circles_[std::size_t(c)];
  circle.max_chord_angle = std::min(circle.max_chord_angle, max_chord_angle);
  if (!full_turn(span))
    circle.has_corners = true;
  arcs_.push_back({c, wrap_angle(angle_start), span, 0, 0});
  return int(arcs_.size() - 1);
}

int CircleSet2D::nearest_vertex(const Circle& c, double angle) const {
  int best = 0;
  double best_d = two_pi;
  for (std::size_t j = 0; j < c.angles.size(); ++j) {
    const double d = std::abs(c.angles[j] - angle);
    const double dist = std::min(d, two_pi - d);
    if (dist < best_d)
      best_d = dist, best = int(j);
  }
  return best;
}

void CircleSet2D::finalize() {
  for (std::size_t ci = 0; ci < circles_.size(); ++ci) {
    Circle& c = circles_[ci];
    const double step = c.max_chord_angle * (c.has_corners ? corner_grid_shrink : 1.0);
    const int n = std::max(3, int(std::ceil(two_pi / step - 1e-9)));
    c.angles.resize(std::size_t(n));
    for (int k = 0; k < n; ++k)
      c.angles[std::size_t(k)] = two_pi * k / n;
    // Corners replace the nearest grid angle; coinciding corners share one vertex.
    std::vector<double> corners;
    for (const Arc& a : arcs_)
      if (a.circle == int(ci) && !full_turn(a.span)) {
        corners.push_back(a.start);
        corners.push_back(wrap_angle(a.start + a.span));
      }
    std::vector<char> replaced(std::size_t(n), 0);
    std::vector<double> extra;
    for (double f : corners) {
      const int j = int(std::lround(f / (two_pi / n))) % n;
      if (!replaced[std::size_t(j)]) {
        c.angles[std::size_t(j)] = f;
        replaced[std::size_t(j)] = 1;
      } else if (std::abs(c.angles[std::size_t(j)] - f) > same_angle_tol &&
                 std::none_of(extra.begin(), extra.end(),
                              [&](double e) { return std::abs(e - f) <= same_angle_tol; })) {
        extra.push_back(f);
      }
    }
    c.angles.insert(c.angles.end(), extra.begin(), extra.end());
    std::sort(c.angles.begin(), c.angles.end());
    c.points.clear();
    for (double a : c.angles)
      c.points.push_back(c.center + c.radius * Vec2(std::cos(a), std::sin(a)));
  }
  for (Arc& a : arcs_) {
    if (full_turn(a.span))
      continue;
    const Circle& c = circles_[std::size_t(a.circle)];
    a.first = nearest_vertex(c, a.start);
    a.last = nearest_vertex(c, wrap_angle(a.start + a.span));
  }
}

std::vector<Vec2> CircleSet2D::arc_points(int arc) const {
  const Arc& a = arcs_[std::size_t(arc)];
  const Circle& c = circles_[std::size_t(a.circle)];
  if (full_turn(a.span))
    return c.points;
  std::vector<Vec2> out;
  const int n = int(c.points.size());
  for (int j = a.first;; j = (j + 1) % n) {
    out.push_back(c.points[std::size_t(j)]);
    if (j == a.last)
      break;
  }
  return out;
}

bool CircleSet2D::inside(int circle, const Vec2& p) const {
  const Circle& c = circles_[std::size_t(circle)];
  const Vec2 d = p - c.center;
  const double r2 = d.squaredNorm();
  if (r2 >= c.radius * c.radius)
    return false;
  const double t = wrap_angle(std::atan2(d.y(), d.x()));
  // Chord from angle a0 to a1 (a1 may pass 2 pi) containing direction t.
  const auto it = std::upper_bound(c.angles.begin(), c.angles.end(), t);
  double a0 = 0, a1 = 0;
  if (it == c.angles.begin() || it == c.angles.end()) {
    a0 = c.angles.back();
    a1 = c.angles.front() + two_pi;
  } else {
    a0 = *(it - 1);
    a1 = *it;
  }
  const double mid = 0.5 * (a0 + a1), half = 0.5 * (a1 - a0);
  return d.x() * std::cos(mid) + d.y() * std::sin(mid) < c.radius * std::cos(half);
}

double CircleSet2D::max_sagitta(int circle) const {
  const Circle& c = circles_[std::size_t(circle)];
  double gap = c.angles.front() + two_pi - c.angles.back();
  for (std::size_t j = 1; j < c.angles.size(); ++j)
    gap = std::max(gap, c.angles[j] - c.angles[j - 1]);
  return c.radius * (1 - std::cos(0.5 * gap));
}

} // namespace magfem
