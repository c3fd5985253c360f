#include "casefile/symmetry_check3d.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "casefile/symmetry_cut_factor.hpp"
#include "core/input_error.hpp"
#include "mesh/grid_frame3d.hpp"
#include "sources/coil_field.hpp"

namespace magfem {
namespace {

constexpr int samples_per_axis = 6;
constexpr double source_rel_tol = 1e-6; // remanence and current density are exact images

// Interior points of a part: cell midpoints of a grid in its own coordinates.
std::vector<Vec3> interior_points(const Part3D& part) {
  std::vector<Vec3> out;
  const int n = samples_per_axis;
  auto mid = [n](double lo, double hi, int i) { return lo + (i + 0.5) * (hi - lo) / n; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        Vec3 l;
        if (const auto* s = std::get_if<SphericalSegment>(&part.shape)) {
          const double r = mid(s->r_inner, s->r_outer, i), t = mid(s->theta_min, s->theta_max, j);
          const double p = mid(s->phi_min, s->phi_max, k);
          l = r * Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
        } else if (const auto* c = std::get_if<Cylinder>(&part.shape)) {
          const double r = mid(c->r_inner, c->r_outer, i), a = mid(0, 2 * std::numbers::pi, j);
          l = Vec3(r * std::cos(a), r * std::sin(a), mid(0, c->height, k));
        } else {
          const Vec3 h = std::get<Box>(part.shape).size / 2;
          l = Vec3(mid(-h.x(), h.x(), i), mid(-h.y(), h.y(), j), mid(-h.z(), h.z(), k));
        }
        out.push_back(part.placement.to_global(l));
      }
  return out;
}

std::string where(const Vec3& x, const CaseSpec& spec) {
  char buf[160];
  const Vec3 u = x / spec.length_unit;
  std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g) %s", u.x(), u.y(), u.z(),
                spec.unit_name.c_str());
  return buf;
}

std::string plane_text(const SymmetryPlane3D& p) {
  return std::string("symmetry plane ") + axis_name(p.axis) +
         " = 0 (field: " + field_name(p.field) + ")";
}

const char* magnet_rule =
    "a magnet magnetized along the plane's normal is its own mirror image with field: normal, "
    "one magnetized along the plane with field: parallel";
const char* coil_rule = "a coil whose current runs parallel to the plane (axis along its normal) "
                        "is its own mirror image with field: normal, one whose current crosses "
                        "the plane (axis in the plane) with field: parallel";

void check_parts(const CaseSpec& spec, const SymmetryPlane3D& plane) {
  const auto& parts = spec.geometry3d.parts;
  const Mat3 r = reflection(plane);
  // Image of the remanence direction: M(R x) must equal m_map M(x).
  const Mat3 m_map = plane.field == SymmetryField::normal ? Mat3(-r) : r;
  const double tol = 1e-9 * spec.geometry3d.outer.radius;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const RegionSpec& reg = spec.regions[i];
    auto fail = [&](const std::string& why) {
      throw InputError(spec.file, reg.line, "regions[" + std::to_string(i) + "]",
                       "part '" + reg.name + "' is not symmetric about the " + plane_text(plane) +
                           ": " + why);
    };
    for (const Vec3& x : interior_points(parts[i])) {
      const Vec3 y = r * x;
      std::size_t q = 0;
      while (q < parts.size() && !part_contains(parts[q], y, tol))
        ++q;
      if (q == parts.size())
        fail("the mirror image of its point " + where(x, spec) + " lies in air");
      const RegionSpec& img = spec.regions[q];
      // By content: a magnet at its own temperature has a material of its own (own_material).
      if (img.material != reg.material &&
          (img.material->name != reg.material->name || img.material->B_r != reg.material->B_r ||
           img.material->mu_r != reg.material->mu_r))
        fail("the mirror image of its point " + where(x, spec) + " lies in part '" + img.name +
             "' of material '" + img.material->name + "', not '" + reg.material->name + "'");
      const Vec3 m = reg.magnetization.unit_at(x), m_img = img.magnetization.unit_at(y);
      if ((m_img - m_map * m).norm() > source_rel_tol * std::max(m.norm(), 1.0))
        fail(std::string("its magnetization at ") + where(x, spec) +
             (q == i ? " is not its own mirror image under this condition"
                     : " is not the mirror image of part '" + img.name + "''s") +
             " (" + magnet_rule + ")");
    }
  }
}

void check_coils(const CaseSpec& spec, const SymmetryPlane3D& plane) {
  const auto& coils = spec.geometry3d.coils;
  const Mat3 r = reflection(plane);
  const Mat3 j_map = plane.field == SymmetryField::normal ? r : Mat3(-r);
  std::vector<CoilField> fields;
  for (const Coil3D& c : coils)
    fields.emplace_back(c);
  for (std::size_t k = 0; k < coils.size(); ++k) {
    auto fail = [&](const std::string& why) {
      throw InputError(spec.file, spec.coil_lines[k], "coils." + coils[k].name,
                       "coil '" + coils[k].name + "' is not symmetric about the " +
                           plane_text(plane) + ": " + why);
    };
    for (const CoilQuadraturePoint& q : fields[k].volume_quadrature(3)) {
      const Vec3 y = r * q.x;
      const Vec3 j = fields[k].current_density(q.x);
      const double scale = source_rel_tol * std::max(j.norm(), 1e-300);
      if ((fields[k].current_density(y) - j_map * j).norm() <= scale)
        continue;
      Vec3 j_all_x = Vec3::Zero(), j_all_y = Vec3::Zero();
      std::string image;
      for (std::size_t i = 0; i < fields.size(); ++i) {
        j_all_x += fields[i].current_density(q.x);
        j_all_y += fields[i].current_density(y);
        if (i != k && fields[i].current_density(y).norm() > scale)
          image = coils[i].name;
      }
      // Axisymmetric cases take such pairs (pipeline/coil_results_axi.hpp); in 3D the second
      // sensitivity solve with the plane's other condition is not done yet.
      if ((j_all_y - j_map * j_all_x).norm() <= scale)
        fail("its mirror image is another coil ('" + image +
             "'); coil pairs mirrored into each other are supported in axisymmetric cases "
             "only (their inductance matrix needs a second solve with the plane's other "
             "condition, not done in 3D): in 3D each coil must be its own mirror image; "
             "model both as one coil or leave the plane out");
      fail("the current density at " + where(q.x, spec) + " is not mirrored at " + where(y, spec) +
           " (" + coil_rule + ")");
    }
  }
}

} // namespace

std::vector<double> region_symmetry_factors(const CaseSpec& spec) {
  std::vector<double> out;
  const double tol = 1e-9 * spec.geometry3d.outer.radius;
  for (const Part3D& part : spec.geometry3d.parts) {
    out.push_back(symmetry_cut_factor(interior_points(part), spec.geometry3d.symmetry, tol));
  }
  return out;
}

std::vector<int> share_images(const CaseSpec& spec) {
  const auto& parts = spec.geometry3d.parts;
  const auto& planes = spec.geometry3d.symmetry;
  const double tol = 1e-9 * spec.geometry3d.outer.radius;
  std::vector<int> out(parts.size(), -1);
  if (planes.empty())
    return out; // (and no surface parts to sample: they are refused with planes)
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Part3D& part = parts[i];
    const std::vector<Vec3> xs = interior_points(part);
    if (!wholly_beyond_planes(xs, planes, tol))
      continue;
    const Vec3 y = fold_point(planes, xs.front()).point;
    for (std::size_t q = 0; q < parts.size() && out[i] < 0; ++q)
      if (part_contains(parts[q], y, tol))
        out[i] = int(q);
  }
  return out;
}

void check_symmetry_3d(const CaseSpec& spec) {
  if (spec.geometry3d.symmetry.empty())
    return;
  // A CAD surface would have to be cut at the plane and its mirror matched triangle by
  // triangle: not done, so say so rather than mesh a share that may not be one.
  for (std::size_t i = 0; i < spec.geometry3d.parts.size(); ++i)
    if (std::holds_alternative<TriangleSurface>(spec.geometry3d.parts[i].shape))
      throw InputError(spec.file, spec.regions[i].line, "regions[" + std::to_string(i) + "]",
                       "part '" + spec.regions[i].name +
                           "' is a surface (STL) part, which cannot be used with symmetry "
                           "planes: model the whole device (remove boundary.symmetry)");
  for (const SymmetryPlane3D& plane : spec.geometry3d.symmetry) {
    check_parts(spec, plane);
    check_coils(spec, plane);
  }
}

} // namespace magfem
