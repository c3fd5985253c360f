#include "analytic/radial_field_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {

RadialFieldTable::RadialFieldTable(const FieldAtPoints& b_rotor, std::vector<double> radii,
                                   double step_rad)
    : radii_(std::move(radii)) {
  if (radii_.empty() || !(step_rad > 0))
    throw std::invalid_argument("RadialFieldTable: needs radii and a positive step");
  std::sort(radii_.begin(), radii_.end());
  n_theta_ = static_cast<int>(std::ceil(pi / step_rad - 1e-9));
  n_phi_ = 2 * n_theta_;
  step_ = pi / n_theta_;
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> normals;
  points.reserve(radii_.size() * static_cast<std::size_t>((n_theta_ + 1) * n_phi_));
  for (const double r : radii_) {
    if (!(r > 0))
      throw std::invalid_argument("RadialFieldTable: radii must be positive");
    for (int i = 0; i <= n_theta_; ++i)
      for (int j = 0; j < n_phi_; ++j) {
        const double t = i * step_, p = j * step_;
        const Eigen::Vector3d n(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
        points.push_back(r * n);
        normals.push_back(n);
      }
  }
  const auto b = b_rotor(points);
  if (b.size() != points.size())
    throw std::logic_error("RadialFieldTable: the field returned the wrong number of values");
  values_.resize(b.size());
  for (std::size_t k = 0; k < b.size(); ++k)
    values_[k] = b[k].dot(normals[k]);
}

double RadialFieldTable::at(std::size_t radius, int i, int j) const {
  if (i < 0) { // over the north pole: (-theta, phi) is (theta, phi + pi)
    i = -i;
    j += n_theta_;
  } else if (i > n_theta_) { // over the south pole
    i = 2 * n_theta_ - i;
    j += n_theta_;
  }
  j %= n_phi_;
  if (j < 0)
    j += n_phi_;
  return values_[(radius * static_cast<std::size_t>(n_theta_ + 1) + static_cast<std::size_t>(i)) *
                     static_cast<std::size_t>(n_phi_) +
                 static_cast<std::size_t>(j)];
}

namespace {
// Cubic Lagrange weights on the nodes -1, 0, 1, 2 at t in [0, 1).
void cubic_weights(double t, double w[4]) {
  w[0] = -t * (t - 1) * (t - 2) / 6;
  w[1] = (t + 1) * (t - 1) * (t - 2) / 2;
  w[2] = -(t + 1) * t * (t - 2) / 2;
  w[3] = (t + 1) * t * (t - 1) / 6;
}
} // namespace

double RadialFieldTable::radial(std::size_t radius, double theta, double phi) const {
  const double u = theta / step_, v = phi / step_;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  double wu[4], wv[4];
  cubic_weights(u - i0, wu);
  cubic_weights(v - j0, wv);
  double sum = 0;
  for (int a = 0; a < 4; ++a) {
    double row = 0;
    for (int b = 0; b < 4; ++b)
      row += wv[b] * at(radius, i0 - 1 + a, j0 - 1 + b);
    sum += wu[a] * row;
  }
  return sum;
}

std::vector<Eigen::Vector3d>
RadialFieldTable::operator()(const std::vector<Eigen::Vector3d>& points) const {
  std::vector<Eigen::Vector3d> out;
  out.reserve(points.size());
  for (const auto& x : points) {
    const double r = x.norm();
    const auto it = std::lower_bound(radii_.begin(), radii_.end(), r * (1 - 1e-9));
    if (it == radii_.end() || std::abs(*it - r) > 1e-9 * r)
      throw std::invalid_argument("RadialFieldTable: a point is off the tabulated spheres");
    const auto k = static_cast<std::size_t>(it - radii_.begin());
    const double theta = std::acos(std::clamp(x.z() / r, -1.0, 1.0));
    double phi = std::atan2(x.y(), x.x());
    if (phi < 0)
      phi += 2 * pi;
    out.push_back(radial(k, theta, phi) * x / r);
  }
  return out;
}

std::vector<double> quadrature_radii(const std::vector<CoilField>& coils, const CoilRule& rule) {
  std::vector<double> radii;
  for (const auto& c : coils)
    for (const auto& q : torque_quadrature(c, rule))
      radii.push_back(q.x.norm());
  std::sort(radii.begin(), radii.end());
  std::vector<double> distinct;
  for (const double r : radii)
    if (distinct.empty() || r > distinct.back() * (1 + 1e-9))
      distinct.push_back(r);
  return distinct;
}

} // namespace magfem
