#pragma once
// Small parsing helpers shared by the 2D and 3D parts of the case reader.
#include <string>

#include <Eigen/Core>

#include "core/yaml_node.hpp"

namespace magfem {

class MaterialLibrary;
struct CaseSpec;
struct RegionSpec;

double unit_scale(const YamlNode& node);
Eigen::Vector2d read_point2(const YamlNode& node, double scale);
Eigen::Vector3d read_point3(const YamlNode& node, double scale);
// A non-zero direction, normalised.
Eigen::Vector3d read_direction3(const YamlNode& node);
// [min, max] in degrees -> radians, with min < max and both within [lo, hi] degrees.
std::pair<double, double> read_angle_range(const YamlNode& node, double lo, double hi);

// The material of a region (default air) into spec.material; magnets must have a
// magnetization node and non-magnets must not (the caller reads it).
void read_region_material(const YamlNode& region, const CaseSpec& c, const MaterialLibrary& lib,
                          RegionSpec& spec);

// Region readers for each dimension: append parts and region specs to the case.
void read_regions_2d(const YamlNode& regions, CaseSpec& c, const MaterialLibrary& lib);
void read_regions_3d(const YamlNode& regions, CaseSpec& c, const MaterialLibrary& lib);
// The coils: section of a 3D case (after the regions: names must not collide).
void read_coils_3d(const YamlNode& coils, CaseSpec& c);

} // namespace magfem
