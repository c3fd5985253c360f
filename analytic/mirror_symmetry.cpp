#include "analytic/mirror_symmetry.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "analytic/charge_source.hpp"

namespace magfem {

namespace {

using Vec3 = Eigen::Vector3d;

constexpr int fingerprint_order = 3;
constexpr double match_tolerance = 1e-9; // relative to the group's size and largest charge

// A magnet's charges at fixed nodes (see the header), with their centroid as a quick key.
struct Fingerprint {
  std::vector<PointCharge> charges;
  Vec3 centroid = Vec3::Zero();
};

Fingerprint fingerprint(const AnalyticMagnet& m) {
  Fingerprint f;
  const GaussRule rule(fingerprint_order);
  for (const ChargeDomain& d : charge_domains(m))
    for (const ParamBox& b : root_boxes(d, pi / 4))
      d.quadrature(b, rule, f.charges);
  for (const PointCharge& p : f.charges)
    f.centroid += p.x;
  if (!f.charges.empty())
    f.centroid /= static_cast<double>(f.charges.size());
  return f;
}

struct Scales {
  double length = 0, charge = 0;
};

Scales scales_of(const std::vector<Fingerprint>& group, const Vec3& point) {
  Scales s;
  for (const Fingerprint& f : group)
    for (const PointCharge& p : f.charges) {
      s.length = std::max(s.length, (p.x - point).norm());
      s.charge = std::max(s.charge, std::abs(p.q));
    }
  return s;
}

// The sign s with which the mirror image of `a` is `b`, or 0 if it is not.
double image_sign(const MirrorSymmetry& m, const Fingerprint& a, const Fingerprint& b,
                  const Scales& sc) {
  const double dx = match_tolerance * sc.length, dq = match_tolerance * sc.charge;
  if (a.charges.size() != b.charges.size())
    return 0;
  if (a.charges.empty())
    return 1;
  const Vec3 centroid = m.point + m.reflect(a.centroid - m.point);
  if ((centroid - b.centroid).norm() > dx)
    return 0;
  double sign = 0;
  for (const PointCharge& p : a.charges) {
    const Vec3 x = m.point + m.reflect(p.x - m.point);
    const auto hit = std::find_if(b.charges.begin(), b.charges.end(),
                                  [&](const PointCharge& c) { return (c.x - x).norm() <= dx; });
    if (hit == b.charges.end())
      return 0;
    if (sign == 0 && std::abs(p.q) > dq)
      sign = hit->q * p.q > 0 ? 1 : -1;
    if (std::abs(hit->q - (sign == 0 ? 1 : sign) * p.q) > dq)
      return 0;
  }
  return sign == 0 ? 1 : sign;
}

// Images and signs of a whole group, or false if some magnet has no image.
bool map_group(MirrorSymmetry& m, const std::vector<Fingerprint>& group, std::vector<int>& image,
               std::vector<double>& sign) {
  const Scales sc = scales_of(group, m.point);
  image.assign(group.size(), -1);
  sign.assign(group.size(), 0);
  for (std::size_t i = 0; i < group.size(); ++i) {
    for (std::size_t k = 0; k < group.size() && image[i] < 0; ++k) {
      const double s = image_sign(m, group[i], group[k], sc);
      if (s != 0)
        image[i] = static_cast<int>(k), sign[i] = s;
    }
    if (image[i] < 0)
      return false;
  }
  // The pairing must be an involution (coincident duplicate magnets would break it).
  for (std::size_t i = 0; i < group.size(); ++i)
    if (image[static_cast<std::size_t>(image[i])] != static_cast<int>(i))
      return false;
  return true;
}

} // namespace

Vec3 MirrorSymmetry::reflect(const Vec3& v) const {
  return v - 2 * v.dot(normal) * normal;
}

std::optional<MirrorSymmetry> find_mirror_symmetry(const std::vector<AnalyticMagnet>& on,
                                                   const std::vector<AnalyticMagnet>& by,
                                                   const Vec3& point) {
  std::vector<Fingerprint> fa, fb;
  for (const AnalyticMagnet& m : on)
    fa.push_back(fingerprint(m));
  for (const AnalyticMagnet& m : by)
    fb.push_back(fingerprint(m));
  for (int axis = 0; axis < 3; ++axis) {
    MirrorSymmetry m;
    m.point = point;
    m.normal = Vec3::Unit(axis);
    if (map_group(m, fa, m.image_on, m.sign_on) && map_group(m, fb, m.image_by, m.sign_by))
      return m;
  }
  return std::nullopt;
}

} // namespace magfem
