#include "analytic/spherical_imaging.hpp"

namespace magfem {

Eigen::Vector3d invert(const Inversion& inv, const Eigen::Vector3d& x) {
  const Eigen::Vector3d d = x - inv.centre;
  return inv.centre + (inv.radius * inv.radius / d.squaredNorm()) * d;
}

PointCharge ImageMap::apply(const PointCharge& source) const {
  PointCharge p = source;
  for (const Inversion& inv : chain_) {
    const Eigen::Vector3d d = p.x - inv.centre;
    const double r2 = d.squaredNorm();
    // Opposite sign: the image cancels the source's potential on the sphere.
    p.q *= -inv.radius / std::sqrt(r2);
    p.x = inv.centre + (inv.radius * inv.radius / r2) * d;
  }
  return p;
}

Eigen::Vector3d ImageMap::preimage(const Eigen::Vector3d& x) const {
  Eigen::Vector3d y = x;
  for (auto it = chain_.rbegin(); it != chain_.rend(); ++it)
    y = invert(*it, y);
  return y;
}

std::vector<std::vector<int>> image_chains(int n_spheres, int order) {
  std::vector<std::vector<int>> all, level;
  for (int s = 0; s < n_spheres; ++s)
    level.push_back({s});
  for (int len = 1; len <= order && !level.empty(); ++len) {
    all.insert(all.end(), level.begin(), level.end());
    std::vector<std::vector<int>> next;
    for (const auto& chain : level)
      for (int s = 0; s < n_spheres; ++s)
        if (s != chain.back()) {
          next.push_back(chain);
          next.back().push_back(s);
        }
    level = std::move(next);
  }
  return all;
}

} // namespace magfem
