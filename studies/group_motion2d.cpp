#include "studies/group_motion2d.hpp"

#include <Eigen/Geometry>

#include "core/input_error.hpp"

namespace magfem {
namespace {

// Each shape carried by the motion: its reference points move, its orientation turns.
struct Carry {
  const RigidMotion2D& m;
  void operator()(Disk& s) const { s.center = m.at(s.center); }
  void operator()(Annulus& s) const { s.center = m.at(s.center); }
  void operator()(AnnularSector& s) const {
    s.center = m.at(s.center);
    s.angle_start += m.angle_rad;
    s.angle_end += m.angle_rad;
  }
  void operator()(Rectangle& s) const {
    s.center = m.at(s.center);
    s.rotation += m.angle_rad;
  }
  void operator()(Polygon& s) const {
    for (Vec2& v : s.vertices)
      v = m.at(v);
  }
};

} // namespace

Vec2 RigidMotion2D::at(const Vec2& x) const {
  return center + Eigen::Rotation2Dd(angle_rad) * (x - center) + shift;
}

CaseSpec move_group2d(const CaseSpec& spec, const std::string& group, const RigidMotion2D& motion,
                      const std::string& option) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(motion.angle_rad, Eigen::Vector3d::UnitZ()).matrix();
  CaseSpec out = spec;
  bool found = false;
  for (std::size_t i = 0; i < out.regions.size(); ++i) {
    if (out.regions[i].group != group)
      continue;
    found = true;
    std::visit(Carry{motion}, out.geometry2d.parts[i].shape);
    Magnetization& m = out.regions[i].magnetization;
    m.direction = R * m.direction;
    m.center.head<2>() = motion.at(m.center.head<2>());
  }
  if (!found)
    throw InputError("<command line>", 0, option,
                     "no region of " + spec.file + " is in group '" + group + "'");
  return out;
}

} // namespace magfem
