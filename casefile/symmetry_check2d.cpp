#include "casefile/symmetry_check2d.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "casefile/symmetry_cut_factor.hpp"
#include "core/input_error.hpp"

namespace magfem {
namespace {

constexpr int samples_per_axis = 12;
constexpr double source_rel_tol = 1e-6; // remanence and current density are exact images

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Whether x lies in the exact shape, or within tol of it.
bool shape_contains(const Shape2D& shape, const Vec2& x, double tol) {
  if (const auto* d = std::get_if<Disk>(&shape))
    return (x - d->center).norm() < d->radius + tol;
  if (const auto* a = std::get_if<Annulus>(&shape)) {
    const double r = (x - a->center).norm();
    return r > a->r_inner - tol && r < a->r_outer + tol;
  }
  if (const auto* s = std::get_if<AnnularSector>(&shape)) {
    const Vec2 v = x - s->center;
    const double r = v.norm();
    if (!(r > s->r_inner - tol && r < s->r_outer + tol))
      return false;
    if (r <= tol)
      return true;
    const double two_pi = 2 * std::numbers::pi, slack = tol / r;
    const double a = std::remainder(std::atan2(v.y(), v.x()) - s->angle_start + slack, two_pi);
    return (a < 0 ? a + two_pi : a) < s->angle_end - s->angle_start + 2 * slack;
  }
  if (const auto* r = std::get_if<Rectangle>(&shape)) {
    const Vec2 q = Eigen::Rotation2Dd(-r->rotation) * (x - r->center);
    return std::abs(q.x()) < 0.5 * r->width + tol && std::abs(q.y()) < 0.5 * r->height + tol;
  }
  const auto& v = std::get<Polygon>(shape).vertices;
  bool inside = false;
  for (std::size_t i = 0, n = v.size(); i < n; ++i) {
    const Vec2 &a = v[i], &b = v[(i + 1) % n];
    const Vec2 e = b - a;
    const double t = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    if ((a + t * e - x).norm() < tol)
      return true;
    if ((a.y() > x.y()) != (b.y() > x.y()) && cross(b - a, x - a) * (b.y() - a.y()) > 0)
      inside = !inside;
  }
  return inside;
}

// The part at x as the mesher decides it (the last containing it wins), or -1 in air.
int part_at(const Geometry2D& g, const Vec2& x, double tol) {
  for (std::size_t i = g.parts.size(); i-- > 0;)
    if (shape_contains(g.parts[i].shape, x, tol))
      return int(i);
  return -1;
}

std::pair<Vec2, Vec2> bounding_box(const Shape2D& shape) {
  if (const auto* d = std::get_if<Disk>(&shape))
    return {d->center.array() - d->radius, d->center.array() + d->radius};
  if (const auto* a = std::get_if<Annulus>(&shape))
    return {a->center.array() - a->r_outer, a->center.array() + a->r_outer};
  if (const auto* s = std::get_if<AnnularSector>(&shape))
    return {s->center.array() - s->r_outer, s->center.array() + s->r_outer};
  std::vector<Vec2> v;
  if (const auto* r = std::get_if<Rectangle>(&shape)) {
    const Eigen::Rotation2Dd rot(r->rotation);
    for (const double sx : {-0.5, 0.5})
      for (const double sy : {-0.5, 0.5})
        v.push_back(r->center + rot * Vec2(sx * r->width, sy * r->height));
  } else {
    v = std::get<Polygon>(shape).vertices;
  }
  Vec2 lo = v.front(), hi = v.front();
  for (const Vec2& p : v)
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return {lo, hi};
}

// Interior points of part i where it is the region (later parts may cover some of it).
std::vector<Vec2> interior_points(const Geometry2D& g, std::size_t i) {
  const auto [lo, hi] = bounding_box(g.parts[i].shape);
  std::vector<Vec2> out;
  const int n = samples_per_axis;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const Vec2 x(lo.x() + (a + 0.5) * (hi.x() - lo.x()) / n,
                   lo.y() + (b + 0.5) * (hi.y() - lo.y()) / n);
      if (part_at(g, x, 0) == int(i))
        out.push_back(x);
    }
  return out;
}

// The plane's reflection acting on 3D vectors (x, y, 0): remanence directions.
Eigen::Matrix3d reflection3(const SymmetryPlane2D& p) {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  r(p.axis, p.axis) = -1;
  return r;
}

std::string where(const Vec2& x, const CaseSpec& spec) {
  char buf[160];
  const Vec2 u = x / spec.length_unit;
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g) %s", u.x(), u.y(), spec.unit_name.c_str());
  return buf;
}

std::string plane_text(const CaseSpec& spec, const SymmetryPlane2D& p) {
  return std::string("symmetry plane ") + plane_name_2d(p, spec.axisymmetric()) +
         " = 0 (field: " + field_name(p.field) + ")";
}

const char* magnet_rule = "a magnet magnetized along the plane's normal is its own mirror image "
                          "with field: normal, one magnetized along the plane with field: "
                          "parallel";
const char* current_rule = "a current and its mirror image flow the same way with field: "
                           "normal, opposite ways with field: parallel; a current region cut "
                           "by the plane needs field: normal";

// The current density a region impresses (A/m^2), ampere-turns over the exact shape's area
// when given as turns (the images of two parts have equal areas).
double current_density(const RegionSpec& r, const Part2D& p) {
  if (r.ampere_turns == 0)
    return r.current_density;
  double area = 0;
  if (const auto* d = std::get_if<Disk>(&p.shape))
    area = std::numbers::pi * d->radius * d->radius;
  else if (const auto* a = std::get_if<Annulus>(&p.shape))
    area = std::numbers::pi * (a->r_outer * a->r_outer - a->r_inner * a->r_inner);
  else if (const auto* s = std::get_if<AnnularSector>(&p.shape))
    area =
        0.5 * (s->angle_end - s->angle_start) * (s->r_outer * s->r_outer - s->r_inner * s->r_inner);
  else if (const auto* q = std::get_if<Rectangle>(&p.shape))
    area = q->width * q->height;
  else {
    const auto& v = std::get<Polygon>(p.shape).vertices;
    for (std::size_t i = 0; i < v.size(); ++i)
      area += 0.5 * cross(v[i], v[(i + 1) % v.size()]);
    area = std::abs(area);
  }
  return r.ampere_turns / area;
}

void check_plane(const CaseSpec& spec, const SymmetryPlane2D& plane) {
  const Geometry2D& g = spec.geometry2d;
  const bool axi = spec.axisymmetric();
  const Eigen::Matrix2d r = reflection_2d(plane);
  const Eigen::Matrix3d r3 = reflection3(plane);
  const Eigen::Matrix3d m_map = plane.field == SymmetryField::normal ? Eigen::Matrix3d(-r3) : r3;
  const double j_sign = plane.field == SymmetryField::normal ? 1 : -1;
  const double tol = 1e-9 * g.outer.radius;
  for (std::size_t i = 0; i < g.parts.size(); ++i) {
    const RegionSpec& reg = spec.regions[i];
    auto fail = [&](const std::string& why) {
      throw InputError(spec.file, reg.line, "regions[" + std::to_string(i) + "]",
                       "region '" + reg.name + "' is not symmetric about the " +
                           plane_text(spec, plane) + ": " + why);
    };
    const double j = current_density(reg, g.parts[i]);
    for (const Vec2& x : interior_points(g, i)) {
      const Vec2 y = r * x;
      const int q = part_at(g, y, tol);
      if (q < 0)
        fail("the mirror image of its point " + where(x, spec) + " lies in air");
      const RegionSpec& img = spec.regions[std::size_t(q)];
      if (img.material != reg.material)
        fail("the mirror image of its point " + where(x, spec) + " lies in region '" + img.name +
             "' of material '" + img.material->name + "', not '" + reg.material->name + "'");
      const Eigen::Vector3d x3(x.x(), x.y(), 0), y3(y.x(), y.y(), 0);
      const Eigen::Vector3d m = reg.magnetization.unit_at(x3),
                            m_img = img.magnetization.unit_at(y3);
      if ((m_img - m_map * m).norm() > source_rel_tol * std::max(m.norm(), 1.0))
        fail(std::string("its magnetization at ") + where(x, spec) +
             (q == int(i) ? " is not its own mirror image under this condition"
                          : " is not the mirror image of region '" + img.name + "''s") +
             " (" + magnet_rule + ")");
      const double j_img = current_density(img, g.parts[std::size_t(q)]);
      if (std::abs(j_img - j_sign * j) > source_rel_tol * std::max(std::abs(j), std::abs(j_img)))
        fail(std::string("its current density at ") + where(x, spec) +
             (q == int(i) ? " is not its own mirror image under this condition"
                          : " is not the mirror image of region '" + img.name + "''s") +
             " (" + current_rule + ")");
      if (axi && (reg.turns != 0) != (img.turns != 0))
        fail("its mirror image is region '" + img.name +
             "', and only one of the two has turns: a coil's image must be a coil too (turns "
             "and current), or neither may be (current_density), for the pair's inductance "
             "matrix");
    }
  }
}

} // namespace

void check_symmetry_2d(const CaseSpec& spec) {
  for (const SymmetryPlane2D& plane : spec.geometry2d.planes)
    check_plane(spec, plane);
}

std::vector<double> region_symmetry_factors_2d(const CaseSpec& spec) {
  const Geometry2D& g = spec.geometry2d;
  const double tol = 1e-9 * g.outer.radius;
  std::vector<double> out;
  for (std::size_t i = 0; i < g.parts.size(); ++i) {
    out.push_back(symmetry_cut_factor(interior_points(g, i), g.planes, tol));
  }
  return out;
}

std::vector<std::vector<int>> mirror_parts_2d(const CaseSpec& spec) {
  const Geometry2D& g = spec.geometry2d;
  const double tol = 1e-9 * g.outer.radius;
  std::vector<std::vector<int>> out;
  for (const SymmetryPlane2D& p : g.planes) {
    std::vector<int> images;
    for (std::size_t i = 0; i < g.parts.size(); ++i) {
      const std::vector<Vec2> xs = interior_points(g, i);
      images.push_back(xs.empty() ? int(i) : part_at(g, reflection_2d(p) * xs.front(), tol));
    }
    out.push_back(std::move(images));
  }
  return out;
}

std::vector<int> share_images_2d(const CaseSpec& spec) {
  const Geometry2D& g = spec.geometry2d;
  const double tol = 1e-9 * g.outer.radius;
  std::vector<int> out(g.parts.size(), -1);
  for (std::size_t i = 0; i < g.parts.size() && !g.planes.empty(); ++i)
    if (const std::vector<Vec2> xs = interior_points(g, i); wholly_beyond_planes(xs, g.planes, tol))
      out[i] = part_at(g, fold_point_2d(g.planes, xs.front()).point, tol);
  return out;
}

} // namespace magfem
