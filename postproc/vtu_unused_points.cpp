#include "postproc/vtu_unused_points.hpp"

#include <algorithm>

namespace magfem {

std::size_t drop_unused_points(VtuGrid& grid) {
  const std::size_t n = grid.points.size();
  std::vector<int> new_index(n, -1);
  for (const int p : grid.connectivity)
    new_index[static_cast<std::size_t>(p)] = 0;
  int kept = 0;
  for (auto& k : new_index)
    if (k == 0)
      k = kept++;
  const std::size_t removed = n - static_cast<std::size_t>(kept);
  if (removed == 0)
    return 0;
  for (int& p : grid.connectivity)
    p = new_index[static_cast<std::size_t>(p)];
  std::size_t w = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (new_index[i] >= 0)
      grid.points[w++] = grid.points[i];
  grid.points.resize(w);
  for (auto& a : grid.point_data) {
    const auto c = static_cast<std::size_t>(a.components);
    w = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (new_index[i] >= 0) {
        std::copy_n(a.values.begin() + static_cast<std::ptrdiff_t>(c * i), c,
                    a.values.begin() + static_cast<std::ptrdiff_t>(c * w));
        ++w;
      }
    a.values.resize(c * w);
  }
  return removed;
}

} // namespace magfem
