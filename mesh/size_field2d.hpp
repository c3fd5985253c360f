#pragma once
// Target element size over the plane (metres): the size of the region containing the point,
// lowered near small-size features and graded away from them,
//   h(x) = max(h_floor, min(region_size(x), min_s [size_s + grading * dist(x, segment_s)])),
// where each source s is a segment carrying a size (a region interface carries the smaller of
// its two regions' sizes; a segment across a thin air gap carries the gap size). The slope
// `grading` bounds the size ratio of neighbouring elements to about 1 + grading.
// Sources are bucketed in a uniform grid; a query visits cells in rings of growing distance and
// stops once no farther source can beat the best size found.
#include <functional>
#include <vector>

#include "mesh/geometry2d.hpp"

namespace magfem {

struct SizeSource2D {
  Vec2 a = Vec2::Zero(), b = Vec2::Zero(); // segment (a == b for a point)
  double size = 0;                         // metres
};

class SizeField2D {
public:
  // region_size: size of the region containing a point (may be +inf outside the domain).
  // box_min/box_max: the area where queries happen (sources outside it are still honoured).
  SizeField2D(std::function<double(const Vec2&)> region_size, std::vector<SizeSource2D> sources,
              double grading, double floor, const Vec2& box_min, const Vec2& box_max);

  double operator()(const Vec2& x) const;
  double grading() const { return grading_; }
  std::size_t n_sources() const { return sources_.size(); }

private:
  void bucket_sources();
  double cell_distance(const Vec2& x, int i, int j) const; // distance from x to cell (i, j)

  std::function<double(const Vec2&)> region_size_;
  std::vector<SizeSource2D> sources_;
  double grading_, floor_;
  Vec2 origin_;
  double cell_ = 1;
  int nx_ = 1, ny_ = 1;
  double min_source_size_ = 0;
  std::vector<int> cell_start_; // CSR: sources of cell c are cell_items_[start[c], start[c+1])
  std::vector<int> cell_items_;
  std::vector<double> cell_min_; // smallest source size in each cell (+inf when empty)
};

} // namespace magfem
