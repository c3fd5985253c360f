#include "casefile/section_reader.hpp"

#include <regex>
#include <set>

#include "casefile/reader_helpers.hpp"

namespace magfem {
namespace {

SectionSpec read_section(const YamlNode& n, const CaseSpec& c) {
  SectionSpec spec;
  spec.line = n.line();
  spec.name = n.at("name").as_string();
  // Names are CSV fields: no separators or quotes to escape.
  static const std::regex safe("[A-Za-z0-9_.-]+");
  if (!std::regex_match(spec.name, safe))
    n.at("name").fail("section names are CSV fields: use letters, digits, '_', '-', '.'");
  const std::string type = n.at("type").as_string();
  const double s = c.length_unit;
  if (c.dimension == 2) {
    if (type != "line")
      n.at("type").fail("unknown section type '" + type + "' for dimension 2 (line)");
    n.allow_keys({"name", "type", "start", "end"});
    spec.kind = SectionSpec::Kind::line;
    spec.start = read_point2(n.at("start"), s);
    spec.end = read_point2(n.at("end"), s);
    if ((spec.end - spec.start).norm() == 0)
      n.at("end").fail("a line section needs two different ends");
    const double domain = c.geometry2d.outer.radius;
    for (const char* key : {"start", "end"}) {
      const Eigen::Vector2d p = std::string(key) == "start" ? spec.start : spec.end;
      if (c.axisymmetric() && p.x() < 0)
        n.at(key).fail("an axisymmetric section lies at r >= 0");
      if (p.norm() >= domain)
        n.at(key).fail("section '" + spec.name + "' leaves the domain (radius " +
                       std::to_string(domain / s) + ")");
    }
    return spec;
  }
  const double domain = c.geometry3d.outer.radius;
  double farthest = 0;
  if (type == "rectangle") {
    n.allow_keys({"name", "type", "center", "normal", "u", "size"});
    spec.kind = SectionSpec::Kind::rectangle;
    spec.frame = read_plane_frame(n, s);
    const Eigen::Vector2d size = read_size2(n.at("size"), s);
    spec.size_u = size.x();
    spec.size_v = size.y();
    farthest = farthest_point(spec.frame, spec.size_u, spec.size_v);
  } else if (type == "disk") {
    n.allow_keys({"name", "type", "center", "normal", "u", "radius"});
    spec.kind = SectionSpec::Kind::disk;
    spec.frame = read_plane_frame(n, s);
    spec.radius = n.at("radius").as_positive() * s;
    farthest = farthest_point_disk(spec.frame, spec.radius);
  } else {
    n.at("type").fail("unknown section type '" + type + "' for dimension 3 (rectangle, disk)");
  }
  if (farthest >= domain)
    n.at(type == "disk" ? "radius" : "size")
        .fail("section '" + spec.name + "' leaves the domain (radius " +
              std::to_string(domain / s) + "; its farthest point is at " +
              std::to_string(farthest / s) + ")");
  return spec;
}

} // namespace

void read_sections(const YamlNode& list, CaseSpec& c) {
  std::set<std::string> names;
  for (const auto& n : list.items()) {
    c.sections.push_back(read_section(n, c));
    if (!names.insert(c.sections.back().name).second)
      n.at("name").fail("duplicate section name '" + c.sections.back().name + "'");
  }
}

} // namespace magfem
