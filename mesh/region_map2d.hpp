#pragma once
// The regions of a 2D geometry as polygons: the outline of every part, of the domain disk and of
// the open-boundary shell, with "the last part containing a point wins" and a target size per
// region. Everything the mesher classifies goes through region_of(), so a triangle's region is
// decided by the same polygons that were inserted as constraints.
#include <functional>
#include <optional>
#include <vector>

#include "mesh/geometry2d.hpp"
#include "mesh/mesh2d.hpp"
#include "mesh/outline2d.hpp"

namespace magfem {

inline constexpr int region_outside = -3; // beyond the outermost circle

class RegionMap2D {
public:
  // Chord limit for the boundary of `region` (part index, region_background for the domain
  // circle, region_shell for the outer shell circle) at a point.
  using Limit = std::function<double(int region, const Vec2&)>;

  // Validates the options, the outer boundary and every part (MeshError naming the part and
  // field) and discretises all outlines. shell_size = 0 derives the shell size from the domain
  // circle's chord length: min(chord, (R2 - R1) / 4 * min(1, size_scale)).
  RegionMap2D(const Geometry2D& geometry, const Limit& limit, double shell_size = 0);

  // Part index, region_background, region_shell or region_outside for a point.
  int region_of(const Vec2& p) const;
  // Target element size of a region (metres, size_scale applied; +inf for region_outside).
  double size_of(int region) const;

  std::size_t n_parts() const { return parts_.size(); }
  const Outline2D& part(std::size_t i) const { return parts_[i]; }
  const Outline2D& domain() const { return *domain_; }
  const Outline2D* shell() const { return shell_ ? &*shell_ : nullptr; } // open boundary only
  double shell_size() const { return shell_size_; }
  double max_sagitta() const; // over every outline, metres

private:
  void validate(const Geometry2D& g) const;
  void check_inside_domain(const Geometry2D& g) const;

  std::vector<Outline2D> parts_;
  std::vector<double> part_sizes_;
  std::optional<Outline2D> domain_, shell_;
  double background_size_ = 0, shell_size_ = 0;
};

} // namespace magfem
