#pragma once
// Coarse triangulations of all interface faces (their sample grids cut into triangles) for
// geometric queries before the real surface mesh exists: intersections between parts of
// different frames, and widths of air gaps (first face hit along a ray).
#include <array>
#include <memory>
#include <vector>

#include "mesh/face_chart3d.hpp"
#include "mesh/geometry3d.hpp"
#include "mesh/grid_frame3d.hpp"

namespace magfem {

class FaceSoup3D {
public:
  // spacing[f]: sample spacing of face f (metres).
  FaceSoup3D(const GridDecomposition3D& dec, const std::vector<double>& spacing);
  ~FaceSoup3D();
  FaceSoup3D(const FaceSoup3D&) = delete;
  FaceSoup3D& operator=(const FaceSoup3D&) = delete;

  const std::vector<FaceSamples3D>& samples() const { return samples_; }

  // Throws MeshError naming both parts when faces of different frames intersect or touch,
  // when a part lies inside a part of another frame, or when a part outside frame 0 reaches the
  // domain ball's radius.
  void check_parts(const Geometry3D& geometry) const;

  // Labels (>= 0: part indices; region_shell_3d etc. for the domain's spheres) on either side
  // of the faces whose coarse triangles the triangle (global corners) meets, sorted, unique.
  std::vector<int> labels_met(const std::array<Vec3, 3>& triangle) const;

  // Distance from origin along the unit direction to the first face met at an angle of
  // incidence within about 78 deg of the normal (grazing hits are no gap) and at least
  // min_distance away, ignoring faces that contain origin (the coarse triangles of faces
  // next to the start point cross the ray near it); infinity when none. hit_face, if given,
  // receives the index of the face hit (-1 when none). With parts_only, faces that bound no
  // part (the domain ball and the open-boundary shell) are not met.
  double distance_to_face(const Vec3& origin, const Vec3& direction, double min_distance,
                          int* hit_face = nullptr, bool parts_only = false) const;

private:
  struct Tree;
  const GridDecomposition3D& dec_;
  std::vector<FaceSamples3D> samples_;
  std::vector<int> tri_face_;
  std::unique_ptr<Tree> tree_;
};

} // namespace magfem
