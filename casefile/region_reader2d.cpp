// Regions of a 2D case: primitives in the plane, magnetization angle, currents.
#include <cmath>
#include <set>

#include "casefile/case_spec.hpp"
#include "casefile/reader_helpers.hpp"
#include "core/constants.hpp"

namespace magfem {
namespace {

using Vec2 = Eigen::Vector2d;

// Shape keys allowed per primitive, besides the common region keys.
const std::vector<std::string> region_common = {"name",          "material", "shape",
                                                "magnetization", "current_density",
                                                "turns",         "current", "mesh_size"};

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
    if (ri >= ro) r.at("r_inner").fail("r_inner must be smaller than r_outer");
    return Annulus{center(), ri, ro};
  }
  if (shape == "sector") {
    r.allow_keys(with_common({"center", "r_inner", "r_outer", "angle_start", "angle_end"}));
    const double ri = r.has("r_inner") ? r.at("r_inner").as_non_negative() * s : 0.0;
    const double ro = r.at("r_outer").as_positive() * s;
    if (ri >= ro) r.at("r_inner").fail("r_inner must be smaller than r_outer");
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
    for (const auto& pt : r.at("points").items()) p.vertices.push_back(read_point2(pt, s));
    if (p.vertices.size() < 3) r.at("points").fail("a polygon needs at least 3 points");
    return p;
  }
  shape_node.fail("unknown shape '" + shape + "' (disk, annulus, sector, rectangle, polygon)");
}

Magnetization read_magnetization(const YamlNode& m, double s) {
  m.allow_keys({"type", "angle", "sign", "center"});
  Magnetization out;
  const std::string type = m.at("type").as_string();
  out.sign = m.get_double("sign", 1.0);
  if (out.sign != 1.0 && out.sign != -1.0) m.at("sign").fail("sign must be 1 or -1");
  if (type == "parallel") {
    out.pattern = Magnetization::Pattern::parallel;
    const double a = m.at("angle").as_double() * deg_to_rad;
    out.direction = {std::cos(a), std::sin(a), 0.0};
  } else if (type == "radial") {
    out.pattern = Magnetization::Pattern::radial;
    if (m.has("center")) {
      const Vec2 c = read_point2(m.at("center"), s);
      out.center = {c.x(), c.y(), 0.0};
    }
  } else {
    m.at("type").fail("unknown magnetization type '" + type + "' (parallel, radial)");
  }
  return out;
}

void read_region(const YamlNode& r, double s, const CaseSpec& c, const MaterialLibrary& lib,
                 Part2D& part, RegionSpec& spec) {
  spec.line = r.line();
  spec.name = r.at("name").as_string();
  part.name = spec.name;
  part.shape = read_shape(r, s);
  if (r.has("mesh_size")) part.max_size = r.at("mesh_size").as_positive() * s;
  read_region_material(r, c, lib, spec);
  if (r.has("magnetization")) spec.magnetization = read_magnetization(r.at("magnetization"), s);
  if (r.has("current_density")) spec.current_density = r.at("current_density").as_double();
  if (r.has("turns") || r.has("current")) {
    if (r.has("current_density")) r.fail("give current_density or turns and current, not both");
    spec.ampere_turns = r.at("turns").as_positive() * r.at("current").as_double();
  }
}

} // namespace

void read_regions_2d(const YamlNode& regions, CaseSpec& c, const MaterialLibrary& lib) {
  std::set<std::string> names;
  for (const auto& r : regions.items()) {
    Part2D part;
    RegionSpec spec;
    read_region(r, c.length_unit, c, lib, part, spec);
    if (!names.insert(spec.name).second) r.at("name").fail("duplicate region name '" + spec.name + "'");
    c.geometry2d.parts.push_back(part);
    c.regions.push_back(spec);
  }
}

} // namespace magfem
