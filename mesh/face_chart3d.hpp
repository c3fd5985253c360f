#pragma once
// A 2D chart of one grid face (see grid_frame3d.hpp) for triangulating it in the plane: planar
// faces use plane coordinates, cones and cylinders are unrolled (isometric) and spheres use a
// stereographic projection from the opposite pole (conformal), so shapes in the chart are the
// shapes on the surface and to_3d puts every point exactly on the curved surface.
#include <Eigen/Core>

#include "mesh/grid_frame3d.hpp"

namespace magfem {

class FaceChart3D {
public:
  FaceChart3D(const GridFrame3D& frame, const GridFace3D& face);

  Eigen::Vector2d to_2d(const Vec3& x_global) const; // x must lie on the face's surface
  Vec3 to_3d(const Eigen::Vector2d& uv) const;       // global point on the surface

  // Radius of curvature for the chord tolerance at a global point (infinity on planes).
  double curvature_radius(const Vec3& x_global) const;
  bool is_sphere() const { return type_ == Type::stereo_north || type_ == Type::stereo_south; }

private:
  enum class Type { plane, stereo_north, stereo_south, cone, cylinder };
  const GridFrame3D* frame_;
  Type type_ = Type::plane;
  Vec3 origin_ = Vec3::Zero(), e1_ = Vec3::UnitX(), e2_ = Vec3::UnitY(); // planes (local)
  double radius_ = 0;                                                    // sphere, cylinder
  double cone_angle_ = 0;                                                // theta of a cone
  double mid_angle_ = 0; // unrolling reference angle (cone, cylinder)
};

// Sample points of a face on a regular grid of its two free grid coordinates, spaced at most
// `spacing` (metres) apart on the surface. Row-major: points[i * n2 + j], i along free axis 0.
struct FaceSamples3D {
  std::vector<Vec3> points;
  int n1 = 0, n2 = 0;
};
FaceSamples3D sample_face(const GridFrame3D& frame, const GridFace3D& face, double spacing);

// True when the global point lies on the closure of the face (within tol metres).
bool face_contains(const GridFrame3D& frame, const GridFace3D& face, const Vec3& x_global,
                   double tol);

// Unit normal of the face at a global point, pointing from the label_low to the label_high side.
Vec3 face_normal(const GridFrame3D& frame, const GridFace3D& face, const Vec3& x_global);

} // namespace magfem
