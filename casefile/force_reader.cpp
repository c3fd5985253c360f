#include "casefile/force_reader.hpp"

#include <algorithm>
#include <set>

#include "casefile/reader_helpers.hpp"

namespace magfem {
namespace {

Eigen::Vector3d read_point(const YamlNode& n, double s, int dim) {
  if (dim == 3)
    return read_point3(n, s);
  const Eigen::Vector2d p = read_point2(n, s);
  return {p.x(), p.y(), 0};
}

// A non-empty list of names, each one of `known` (what: "region" or "coil").
std::vector<std::string> read_names(const YamlNode& list, const std::vector<std::string>& known,
                                    const std::string& what) {
  std::vector<std::string> out;
  for (const auto& r : list.items()) {
    const std::string name = r.as_string();
    if (std::find(known.begin(), known.end(), name) == known.end())
      r.fail("no " + what + " named '" + name + "'");
    out.push_back(name);
  }
  if (out.empty())
    list.fail("list at least one " + what);
  return out;
}

ForceSpec read_force(const YamlNode& f, const CaseSpec& c) {
  ForceSpec spec;
  spec.line = f.line();
  spec.name = f.at("name").as_string();
  const std::string type = f.at("type").as_string();
  const double s = c.length_unit;
  const int dim = c.dimension;
  const double domain = dim == 2 ? c.geometry2d.outer.radius : c.geometry3d.outer.radius;
  if (f.has("center"))
    spec.center = read_point(f.at("center"), s, dim);
  spec.torque_point =
      f.has("torque_point") ? read_point(f.at("torque_point"), s, dim) : spec.center;
  if ((type == "circle" && dim == 2) || (type == "sphere" && dim == 3)) {
    f.allow_keys({"name", "type", "center", "radius", "torque_point", "check_radius"});
    spec.kind = dim == 2 ? ForceSpec::Kind::circle : ForceSpec::Kind::sphere;
    spec.radius = f.at("radius").as_positive() * s;
    if (spec.center.norm() + spec.radius >= domain)
      f.at("radius").fail("the surface leaves the meshed domain");
    // Axisymmetric: the circle revolves into a sphere, which is closed only about the axis.
    if (c.axisymmetric() && spec.center.x() != 0)
      f.at("center").fail("an axisymmetric stress circle must be centred on the axis (r = 0)");
    if (f.has("check_radius")) {
      spec.check_radius = f.at("check_radius").as_positive() * s;
      if (spec.center.norm() + spec.check_radius >= domain)
        f.at("check_radius").fail("the surface leaves the meshed domain");
    }
  } else if (type == "band" && dim == 2 && !c.axisymmetric()) {
    f.allow_keys({"name", "type", "center", "r_inner", "r_outer", "torque_point"});
    spec.kind = ForceSpec::Kind::band;
    spec.r_inner = f.at("r_inner").as_positive() * s;
    spec.r_outer = f.at("r_outer").as_positive() * s;
    if (!(spec.r_outer > spec.r_inner))
      f.at("r_outer").fail("r_outer must exceed r_inner");
    if (spec.center.norm() + spec.r_outer >= domain)
      f.at("r_outer").fail("the band leaves the meshed domain");
  } else if (type == "lorentz" && dim == 2) {
    f.allow_keys({"name", "type", "regions", "torque_point"});
    spec.kind = ForceSpec::Kind::lorentz;
    std::vector<std::string> known;
    for (const auto& reg : c.regions)
      known.push_back(reg.name);
    spec.regions = read_names(f.at("regions"), known, "region");
  } else if (type == "contour" && c.axisymmetric()) {
    f.allow_keys({"name", "type", "region", "margin"});
    spec.kind = ForceSpec::Kind::contour;
    std::vector<std::string> known;
    for (const auto& reg : c.regions)
      known.push_back(reg.name);
    const auto region = f.at("region");
    if (std::find(known.begin(), known.end(), region.as_string()) == known.end())
      region.fail("no region named '" + region.as_string() + "'");
    spec.regions = {region.as_string()};
    spec.margin = f.at("margin").as_positive() * s;
  } else if (type == "box" && dim == 3) {
    f.allow_keys({"name", "type", "center", "size", "torque_point", "check_size"});
    spec.kind = ForceSpec::Kind::box;
    spec.size = read_point3(f.at("size"), s);
    if (spec.size.minCoeff() <= 0)
      f.at("size").fail("box sizes must be positive");
    if (spec.center.norm() + 0.5 * spec.size.norm() >= domain)
      f.at("size").fail("the surface leaves the meshed domain");
    if (f.has("check_size")) {
      spec.check_size = read_point3(f.at("check_size"), s);
      if (spec.check_size.minCoeff() <= 0)
        f.at("check_size").fail("box sizes must be positive");
      if (spec.center.norm() + 0.5 * spec.check_size.norm() >= domain)
        f.at("check_size").fail("the surface leaves the meshed domain");
    }
  } else if (type == "lorentz" && dim == 3) {
    f.allow_keys({"name", "type", "coils", "torque_point"});
    spec.kind = ForceSpec::Kind::lorentz;
    std::vector<std::string> known;
    for (const auto& coil : c.geometry3d.coils)
      known.push_back(coil.name);
    spec.regions = read_names(f.at("coils"), known, "coil");
  } else {
    f.at("type").fail("unknown force type '" + type + "' for dimension " + std::to_string(dim) +
                      (c.axisymmetric() ? " (circle, contour, lorentz)"
                       : dim == 2       ? " (circle, band, lorentz)"
                                        : " (sphere, box, lorentz)"));
  }
  return spec;
}

} // namespace

void read_forces(const YamlNode& list, CaseSpec& c) {
  std::set<std::string> names;
  for (const auto& f : list.items()) {
    c.forces.push_back(read_force(f, c));
    if (!names.insert(c.forces.back().name).second)
      f.at("name").fail("duplicate force name '" + c.forces.back().name + "'");
  }
}

} // namespace magfem
