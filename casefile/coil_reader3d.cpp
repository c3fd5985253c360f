// Coils of a 3D case (`coils:` section): circular coils on a sphere (the thesis's), thick
// solenoids and racetracks, each with turns, current, fill factor, resistivity and group.
#include <cmath>
#include <set>

#include <Eigen/Geometry>

#include "casefile/case_spec.hpp"
#include "casefile/reader_helpers.hpp"
#include "core/constants.hpp"

namespace magfem {
namespace {

const std::vector<std::string> common_keys = {
    "name",        "shape",  "turns", "current", "fill_factor", "resistivity",
    "group",       "center", "axis",  "axis_angles", "x_direction"};

std::vector<std::string> keys_with(std::initializer_list<const char*> extra) {
  std::vector<std::string> k = common_keys;
  k.insert(k.end(), extra.begin(), extra.end());
  return k;
}

// Local +z -> axis. `x_direction` (optional) fixes the rotation about the axis (racetracks).
Placement read_frame(const YamlNode& n, double s) {
  Placement p;
  Vec3 axis = Vec3::UnitZ();
  if (n.has("axis") && n.has("axis_angles"))
    n.at("axis_angles").fail("give either axis or axis_angles, not both");
  if (n.has("axis")) {
    axis = read_direction3(n.at("axis"));
  } else if (n.has("axis_angles")) {
    const auto a = n.at("axis_angles").as_doubles(2);
    const double th = a[0] * deg_to_rad, ph = a[1] * deg_to_rad;
    axis = Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
  }
  p.rotation = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), axis).toRotationMatrix();
  if (n.has("x_direction")) {
    Vec3 x = read_direction3(n.at("x_direction"));
    x -= x.dot(axis) * axis;
    if (x.norm() < 1e-9)
      n.at("x_direction").fail("x_direction must not be parallel to the axis");
    x.normalize();
    p.rotation.col(0) = x;
    p.rotation.col(1) = axis.cross(x);
    p.rotation.col(2) = axis;
  }
  if (n.has("center"))
    p.translation = read_point3(n.at("center"), s);
  return p;
}

// Radius of a ball about the local origin that holds the whole bundle.
double bounding_radius(const CoilShape& shape) {
  if (const auto* c = std::get_if<SphericalCoil>(&shape))
    return c->r_outer;
  if (const auto* c = std::get_if<Solenoid>(&shape))
    return std::hypot(c->r_outer, 0.5 * c->length);
  const auto& r = std::get<Racetrack>(shape);
  const double e = r.inner_radius + r.width;
  return std::hypot(std::hypot(0.5 * r.straight_x + e, 0.5 * r.straight_y + e), 0.5 * r.height);
}

CoilShape read_shape(const YamlNode& n, double s) {
  const std::string shape = n.at("shape").as_string();
  if (shape == "circular_coil_on_sphere") {
    n.allow_keys(keys_with({"r_inner", "r_outer", "gap_angle", "bundle_width"}));
    SphericalCoil c;
    c.r_inner = n.at("r_inner").as_positive() * s;
    c.r_outer = n.at("r_outer").as_positive() * s;
    if (c.r_outer <= c.r_inner)
      n.at("r_outer").fail("r_outer must exceed r_inner");
    const double gap = n.at("gap_angle").as_non_negative();
    const double width = n.at("bundle_width").as_positive();
    if (gap + width >= 180)
      n.at("bundle_width").fail("gap_angle + bundle_width must stay below 180 degrees");
    c.alpha_min = gap * deg_to_rad;
    c.alpha_max = (gap + width) * deg_to_rad;
    return c;
  }
  if (shape == "solenoid") {
    n.allow_keys(keys_with({"r_inner", "r_outer", "length"}));
    Solenoid c;
    c.r_inner = n.at("r_inner").as_non_negative() * s;
    c.r_outer = n.at("r_outer").as_positive() * s;
    if (c.r_outer <= c.r_inner)
      n.at("r_outer").fail("r_outer must exceed r_inner");
    c.length = n.at("length").as_positive() * s;
    return c;
  }
  if (shape == "racetrack") {
    n.allow_keys(keys_with({"straight_x", "straight_y", "inner_radius", "width", "height"}));
    Racetrack c;
    c.straight_x = n.at("straight_x").as_non_negative() * s;
    c.straight_y = n.at("straight_y").as_non_negative() * s;
    c.inner_radius = n.at("inner_radius").as_non_negative() * s;
    c.width = n.at("width").as_positive() * s;
    c.height = n.at("height").as_positive() * s;
    return c;
  }
  n.at("shape").fail("unknown coil shape '" + shape +
                     "' (circular_coil_on_sphere, solenoid, racetrack)");
}

} // namespace

void read_coils_3d(const YamlNode& list, CaseSpec& c) {
  if (c.dimension != 3)
    list.fail("coils: in 2D, coils are regions with a current density (see docs/case_format.md)");
  std::set<std::string> names;
  for (const auto& r : c.regions)
    names.insert(r.name);
  const double s = c.length_unit;
  for (const auto& n : list.items()) {
    Coil3D coil;
    coil.name = n.at("name").as_string();
    if (!names.insert(coil.name).second)
      n.at("name").fail("the name '" + coil.name + "' is already used by a region or coil");
    coil.shape = read_shape(n, s);
    coil.placement = read_frame(n, s);
    coil.turns = n.at("turns").as_positive();
    coil.current = n.at("current").as_double();
    if (n.has("fill_factor")) {
      coil.fill_factor = n.at("fill_factor").as_positive();
      if (coil.fill_factor > 1)
        n.at("fill_factor").fail("fill_factor is a fraction of the bundle area (0 < f <= 1)");
    }
    if (n.has("resistivity"))
      coil.resistivity = n.at("resistivity").as_positive();
    if (n.has("group"))
      coil.group = n.at("group").as_string();
    const double reach = coil.placement.translation.norm() + bounding_radius(coil.shape);
    if (reach >= c.geometry3d.outer.radius)
      n.at(n.has("center") ? "center" : "shape")
          .fail("the coil reaches the domain boundary (radius " +
                std::to_string(c.geometry3d.outer.radius / s) + " " + c.unit_name +
                "): enlarge boundary.radius; a closed coil must lie inside it");
    c.geometry3d.coils.push_back(coil);
    c.coil_lines.push_back(n.line());
  }
}

} // namespace magfem
