#include "postproc/tet_plane_cut.hpp"

#include <algorithm>
#include <cmath>

namespace magfem {

TetPlaneCut cut_tet_by_plane(const std::array<Eigen::Vector3d, 4>& x, const PlaneFrame& f) {
  std::array<double, 4> d;
  int above = 0;
  for (int i = 0; i < 4; ++i) {
    d[i] = (x[i] - f.center).dot(f.n);
    above += d[i] >= 0;
  }
  if (above == 0 || above == 4)
    return {};
  TetPlaneCut p;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if ((d[i] >= 0) != (d[j] >= 0)) {
        const Eigen::Vector3d y = x[i] + d[i] / (d[i] - d[j]) * (x[j] - x[i]) - f.center;
        p.emplace_back(y.dot(f.u), y.dot(f.v));
      }
  // The cut is convex: its vertices in angular order about their mean are its boundary.
  Eigen::Vector2d mid = Eigen::Vector2d::Zero();
  for (const auto& y : p)
    mid += y / static_cast<double>(p.size());
  std::sort(p.begin(), p.end(), [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::atan2(a.y() - mid.y(), a.x() - mid.x()) <
           std::atan2(b.y() - mid.y(), b.x() - mid.x());
  });
  return p;
}

} // namespace magfem
