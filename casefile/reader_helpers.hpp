#pragma once
// Small parsing helpers shared by the 2D and 3D parts of the case reader.
#include <string>

#include <Eigen/Core>

#include "core/yaml_node.hpp"
#include "postproc/plane_frame.hpp"

namespace magfem {

class MaterialLibrary;
struct CaseSpec;
struct RegionSpec;

double unit_scale(const YamlNode& node);
Eigen::Vector2d read_point2(const YamlNode& node, double scale);
Eigen::Vector3d read_point3(const YamlNode& node, double scale);
// A non-zero direction, normalised.
Eigen::Vector3d read_direction3(const YamlNode& node);
// The plane of map `node`: `center` (case unit -> metres, scale), `normal` (non-zero) and the
// optional in-plane direction `u` (non-zero, orthogonal to the normal; default
// default_plane_axis(normal)).
PlaneFrame read_plane_frame(const YamlNode& node, double scale);
// A rectangle's `size: [a, b]` (both > 0, case unit -> metres).
Eigen::Vector2d read_size2(const YamlNode& node, double scale);
// The largest distance from the origin of a point of the rectangle size_u x size_v (metres)
// centred in frame f (a corner), or of the disk of radius `radius` centred in f.
double farthest_point(const PlaneFrame& f, double size_u, double size_v);
double farthest_point_disk(const PlaneFrame& f, double radius);
// [min, max] in degrees -> radians, with min < max and both within [lo, hi] degrees.
std::pair<double, double> read_angle_range(const YamlNode& node, double lo, double hi);

// The material of a region (default air) into spec.material; magnets must have a
// magnetization node and non-magnets must not (the caller reads it).
void read_region_material(const YamlNode& region, const CaseSpec& c, const MaterialLibrary& lib,
                          RegionSpec& spec);

// A magnet region's `temperature_C` (default 20) and `HcJ_kApm` (overrides the grade's H_cJ
// at 20 C): spec.material becomes the grade at that temperature (spec.own_material). Called
// by read_region_material; InputError naming the field when they do not apply.
void read_magnet_temperature(const YamlNode& region, RegionSpec& spec);

// Region readers for each dimension: append parts and region specs to the case.
void read_regions_2d(const YamlNode& regions, CaseSpec& c, const MaterialLibrary& lib);
void read_regions_3d(const YamlNode& regions, CaseSpec& c, const MaterialLibrary& lib);
// The coils: section of a 3D case (after the regions: names must not collide).
void read_coils_3d(const YamlNode& coils, CaseSpec& c);

} // namespace magfem
