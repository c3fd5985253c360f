#include "casefile/reader_helpers.hpp"

#include <algorithm>
#include <cmath>

#include "core/input_error.hpp"

#include "casefile/case_spec.hpp"
#include "core/constants.hpp"
#include "materials/material_library.hpp"
#include "materials/material_parser.hpp"

namespace magfem {

double unit_scale(const YamlNode& node) {
  const std::string u = node.as_string();
  if (u == "m")
    return 1.0;
  if (u == "cm")
    return 1e-2;
  if (u == "mm")
    return 1e-3;
  if (u == "um")
    return 1e-6;
  node.fail("unknown length unit '" + u + "' (use m, cm, mm or um)");
}

Eigen::Vector2d read_point2(const YamlNode& node, double scale) {
  const auto v = node.as_doubles(2);
  return Eigen::Vector2d(v[0], v[1]) * scale;
}

Eigen::Vector3d read_point3(const YamlNode& node, double scale) {
  const auto v = node.as_doubles(3);
  return Eigen::Vector3d(v[0], v[1], v[2]) * scale;
}

Eigen::Vector3d read_direction3(const YamlNode& node) {
  const Eigen::Vector3d d = read_point3(node, 1.0);
  if (d.norm() == 0)
    node.fail("a direction must not be the zero vector");
  return d.normalized();
}

PlaneFrame read_plane_frame(const YamlNode& node, double scale) {
  const Eigen::Vector3d center = read_point3(node.at("center"), scale);
  const Eigen::Vector3d n = read_direction3(node.at("normal"));
  if (!node.has("u"))
    return make_plane_frame(center, n, default_plane_axis(n));
  const Eigen::Vector3d u = read_direction3(node.at("u"));
  // 1e-6: the cosine of a direction typed with six digits, e.g. [0.707107, 0.707107, 0].
  if (std::abs(u.dot(n)) > 1e-6)
    node.at("u").fail("u must lie in the plane (orthogonal to the normal)");
  return make_plane_frame(center, n, (u - u.dot(n) * n).normalized());
}

Eigen::Vector2d read_size2(const YamlNode& node, double scale) {
  const auto v = node.as_doubles(2);
  if (!(v[0] > 0 && v[1] > 0))
    node.fail("both sizes must be positive");
  return Eigen::Vector2d(v[0], v[1]) * scale;
}

double farthest_point(const PlaneFrame& f, double size_u, double size_v) {
  double r = 0;
  for (double a : {-0.5, 0.5})
    for (double b : {-0.5, 0.5})
      r = std::max(r, f.at(a * size_u, b * size_v).norm());
  return r;
}

double farthest_point_disk(const PlaneFrame& f, double radius) {
  const double along = f.center.dot(f.n);
  const double across = (f.center - along * f.n).norm();
  return std::hypot(along, across + radius);
}

std::pair<double, double> read_angle_range(const YamlNode& node, double lo, double hi) {
  const auto v = node.as_doubles(2);
  if (!(v[0] < v[1]))
    node.fail("the range must increase ([min, max] in degrees)");
  if (v[0] < lo || v[1] > hi)
    node.fail("the range must lie within [" + std::to_string(lo) + ", " + std::to_string(hi) +
              "] degrees");
  return {v[0] * deg_to_rad, v[1] * deg_to_rad};
}

void read_region_material(const YamlNode& r, const CaseSpec& c, const MaterialLibrary& lib,
                          RegionSpec& spec) {
  const std::string mat = r.has("material") ? r.at("material").as_string() : "air";
  spec.material =
      &resolve_material(mat, c.materials, lib, r.has("material") ? r.at("material") : r);
  if (spec.material->is_magnet() && !r.has("magnetization") && !r.has("pattern"))
    throw InputError(r.file(), r.line(), r.path() + ".magnetization",
                     "magnet region '" + spec.name + "' (material '" + mat +
                         "') needs a magnetization");
  if (!spec.material->is_magnet() && (r.has("magnetization") || r.has("pattern")))
    (r.has("magnetization") ? r.at("magnetization") : r.at("pattern"))
        .fail("material '" + mat + "' is not a permanent magnet");
  read_magnet_temperature(r, spec);
}

void read_magnet_temperature(const YamlNode& r, RegionSpec& spec) {
  const auto temperature = r.find("temperature_C");
  const auto hcj = r.find("HcJ_kApm");
  if (!temperature && !hcj)
    return;
  if (!spec.material->is_magnet())
    (temperature ? *temperature : *hcj)
        .fail("applies to magnet regions only (material '" + spec.material->name +
              "' is not a permanent magnet)");
  Material m = *spec.material;
  if (hcj)
    m.knee.HcJ_Apm = hcj->as_positive() * 1e3;
  if (temperature) {
    const double t = temperature->as_double();
    if (t <= -273.15)
      temperature->fail("a temperature in degrees C must be above -273.15");
    if (t != MagnetKnee::reference_C && !m.knee.alpha_pct_per_K)
      temperature->fail("material '" + m.name +
                        "' has no temperature coefficient of B_r (alpha_Br_pct_per_K): give it "
                        "in the case's materials, or leave temperature_C at 20");
    m = m.at_temperature(t);
    // The linear model run past its range (B_r or H_cJ through zero) describes no magnet.
    const auto hcj_t = m.coercivity_Apm();
    if (m.B_r <= 0 || (hcj_t && *hcj_t <= 0))
      temperature->fail("at " + temperature->as_string() + " C the temperature coefficients of '" +
                        m.name + "' give B_r " + std::to_string(m.B_r) + " T and H_cJ " +
                        (hcj_t ? std::to_string(*hcj_t / 1e3) : std::string("?")) +
                        " kA/m: outside the range they hold for");
  }
  spec.own_material = std::make_shared<const Material>(std::move(m));
  spec.material = spec.own_material.get();
}

} // namespace magfem
