// Regions of a 2D case: primitives in the plane, magnetization angle, currents.
#include <cmath>
#include <optional>
#include <set>

#include <Eigen/Geometry>

#include "casefile/case_spec.hpp"
#include "casefile/reader_helpers.hpp"
#include "core/constants.hpp"

namespace magfem {
namespace {

using Vec2 = Eigen::Vector2d;

// Shape keys allowed per primitive, besides the common region keys.
const std::vector<std::string> region_common = {
    "name",    "material",  "shape", "magnetization", "current_density", "turns",
    "current", "mesh_size", "group", "overlap",       "temperature_C",   "HcJ_kApm"};

std::vector<std::string> with_common(std::initializer_list<const char*> extra) {
  std::vector<std::string> keys = region_common;
  keys.insert(keys.end(), extra.begin(), extra.end());
  return keys;
}

Shape2D read_shape(const YamlNode& r, double s) {
  const auto shape_node = r.at("shape");
  const std::string shape = shape_node.as_string();
  const Vec2 zero = Vec2::Zero();
  auto center = [&] { return r.has("center") ? read_point2(r.at("center"), s) : zero; };
  if (shape == "disk") {
    r.allow_keys(with_common({"center", "radius"}));
    return Disk{center(), r.at("radius").as_positive() * s};
  }
  if (shape == "annulus") {
    r.allow_keys(with_common({"center", "r_inner", "r_outer"}));
    const double ri = r.at("r_inner").as_positive() * s, ro = r.at("r_outer").as_positive() * s;
    if (ri >= ro)
      r.at("r_inner").fail("r_inner must be smaller than r_outer");
    return Annulus{center(), ri, ro};
  }
  if (shape == "sector") {
    r.allow_keys(with_common({"center", "r_inner", "r_outer", "angle_start", "angle_end"}));
    const double ri = r.has("r_inner") ? r.at("r_inner").as_non_negative() * s : 0.0;
    const double ro = r.at("r_outer").as_positive() * s;
    if (ri >= ro)
      r.at("r_inner").fail("r_inner must be smaller than r_outer");
    const double a0 = r.at("angle_start").as_double(), a1 = r.at("angle_end").as_double();
    if (!(a1 > a0) || a1 - a0 > 360.0)
      r.at("angle_end").fail("angle_end must exceed angle_start by at most 360 degrees");
    return AnnularSector{center(), ri, ro, a0 * deg_to_rad, a1 * deg_to_rad};
  }
  if (shape == "rectangle") {
    r.allow_keys(with_common({"center", "width", "height", "rotation"}));
    return Rectangle{center(), r.at("width").as_positive() * s, r.at("height").as_positive() * s,
                     r.get_double("rotation", 0.0) * deg_to_rad};
  }
  if (shape == "polygon") {
    r.allow_keys(with_common({"points"}));
    Polygon p;
    for (const auto& pt : r.at("points").items())
      p.vertices.push_back(read_point2(pt, s));
    if (p.vertices.size() < 3)
      r.at("points").fail("a polygon needs at least 3 points");
    return p;
  }
  shape_node.fail("unknown shape '" + shape + "' (disk, annulus, sector, rectangle, polygon)");
}

// Axisymmetric: the angle is measured in the r-z plane from +r, so `parallel` defaults to
// 90 degrees (axial, +z) and 0 is a radially magnetized ring; `radial` rays start from a
// centre on the axis (spherical radial; a centre off the axis would be a ring of centres,
// which no magnet has).
Magnetization read_magnetization(const YamlNode& m, double s, bool axi) {
  m.allow_keys({"type", "angle", "sign", "center"});
  Magnetization out;
  const std::string type = m.at("type").as_string();
  out.sign = m.get_double("sign", 1.0);
  if (out.sign != 1.0 && out.sign != -1.0)
    m.at("sign").fail("sign must be 1 or -1");
  if (type == "parallel") {
    out.pattern = Magnetization::Pattern::parallel;
    const double a = (axi && !m.has("angle") ? 90.0 : m.at("angle").as_double()) * deg_to_rad;
    out.direction = {std::cos(a), std::sin(a), 0.0};
  } else if (type == "radial") {
    out.pattern = Magnetization::Pattern::radial;
    if (m.has("center")) {
      const Vec2 c = read_point2(m.at("center"), s);
      if (axi && c.x() != 0)
        m.at("center").fail("the centre of a radial magnetization must lie on the axis (r = 0)");
      out.center = {c.x(), c.y(), 0.0};
    }
  } else {
    m.at("type").fail("unknown magnetization type '" + type + "' (parallel, radial)");
  }
  return out;
}

// Smallest x (= r) of each shape, metres.
double min_x(const Disk& d) {
  return d.center.x() - d.radius;
}
double min_x(const Annulus& a) {
  return a.center.x() - a.r_outer;
}
double min_x(const AnnularSector& s) {
  const double a0 = s.angle_start, a1 = s.angle_end;
  const double left = pi + 2 * pi * std::ceil((a0 - pi) / (2 * pi)); // first angle pi >= a0
  const double c = left <= a1 ? -1.0 : std::min(std::cos(a0), std::cos(a1));
  // Every arc of radius r in [r_inner, r_outer] reaches r c; the extremes are the ends.
  return s.center.x() + std::min(s.r_inner * c, s.r_outer * c);
}
double min_x(const std::vector<Vec2>& corners) {
  double x = corners.front().x();
  for (const Vec2& v : corners)
    x = std::min(x, v.x());
  return x;
}
double min_x(const Rectangle& r) {
  const Eigen::Rotation2Dd rot(r.rotation);
  std::vector<Vec2> corners;
  for (const double sx : {-0.5, 0.5})
    for (const double sy : {-0.5, 0.5})
      corners.push_back(r.center + rot * Vec2(sx * r.width, sy * r.height));
  return min_x(corners);
}
double min_x(const Polygon& p) {
  return min_x(p.vertices);
}

// A disk or ring centred on the axis stands for a ball or spherical shell: its r >= 0 half.
std::optional<AnnularSector> half_on_axis(const Disk& d) {
  if (d.center.x() != 0)
    return std::nullopt;
  return AnnularSector{d.center, 0.0, d.radius, -0.5 * pi, 0.5 * pi};
}
std::optional<AnnularSector> half_on_axis(const Annulus& a) {
  if (a.center.x() != 0)
    return std::nullopt;
  return AnnularSector{a.center, a.r_inner, a.r_outer, -0.5 * pi, 0.5 * pi};
}
template <class Shape> std::optional<AnnularSector> half_on_axis(const Shape&) {
  return std::nullopt;
}

// Axisymmetric parts live at r >= 0 (up to the round-off of the unit conversion).
void to_half_plane(const YamlNode& r, Shape2D& shape, double s) {
  const auto half = std::visit([](const auto& v) { return half_on_axis(v); }, shape);
  if (half) {
    shape = *half;
    return;
  }
  if (std::visit([](const auto& v) { return min_x(v); }, shape) < -1e-9 * s)
    r.at("shape").fail("the region crosses the axis into r < 0 (axisymmetric cases live in "
                       "r >= 0; a disk or annulus centred on the axis stands for a ball or "
                       "spherical shell)");
}

void read_region(const YamlNode& r, double s, const CaseSpec& c, const MaterialLibrary& lib,
                 Part2D& part, RegionSpec& spec) {
  const bool axi = c.axisymmetric();
  spec.line = r.line();
  spec.name = r.at("name").as_string();
  part.name = spec.name;
  part.shape = read_shape(r, s);
  if (axi)
    to_half_plane(r, part.shape, s);
  if (r.has("mesh_size"))
    part.max_size = r.at("mesh_size").as_positive() * s;
  if (r.has("overlap")) {
    // The only value: a later region may take area from earlier ones only when it says so.
    if (r.at("overlap").as_string() != "replace")
      r.at("overlap").fail("overlap must be 'replace' (the region takes the area it shares "
                           "with earlier regions); without it regions must not overlap");
    part.replace_earlier = true;
  }
  if (r.has("group")) // sweep --move (axisymmetric) or --rotate (planar)
    spec.group = r.at("group").as_string();
  read_region_material(r, c, lib, spec);
  if (r.has("magnetization"))
    spec.magnetization = read_magnetization(r.at("magnetization"), s, axi);
  if (r.has("current_density"))
    spec.current_density = r.at("current_density").as_double();
  if (r.has("turns") || r.has("current")) {
    if (r.has("current_density"))
      r.fail("give current_density or turns and current, not both");
    spec.turns = r.at("turns").as_positive();
    spec.current = r.at("current").as_double();
    spec.ampere_turns = spec.turns * spec.current;
  }
}

} // namespace

void read_regions_2d(const YamlNode& regions, CaseSpec& c, const MaterialLibrary& lib) {
  std::set<std::string> names;
  for (const auto& r : regions.items()) {
    Part2D part;
    RegionSpec spec;
    read_region(r, c.length_unit, c, lib, part, spec);
    if (!names.insert(spec.name).second)
      r.at("name").fail("duplicate region name '" + spec.name + "'");
    c.geometry2d.parts.push_back(part);
    c.regions.push_back(spec);
  }
}

} // namespace magfem
