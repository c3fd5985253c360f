#pragma once
// Force and torque results of one run, as written to forces.csv and summary.json.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace magfem {

struct ForceResult {
  std::string name;
  std::string method; // stress_sphere, stress_circle, arkkio_band, lorentz
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // N (2D: N/m, or N with a stack length)
  Eigen::Vector3d torque = Eigen::Vector3d::Zero(); // N m (2D: N m/m, or N m with a stack)
  // Consistency check (check_radius given): the same quantity on the second surface, and
  // their difference (relative_difference).
  bool checked = false;
  Eigen::Vector3d check_force = Eigen::Vector3d::Zero();
  Eigen::Vector3d check_torque = Eigen::Vector3d::Zero();
  double check_relative_difference = 0;
  // Error estimate from the one mesh, in the result's units (per component, absolute):
  // `error_method` says how it was made (3D stress tensor: pipeline/force3d.cpp). Not every
  // method has one yet (estimated false: no error_estimate in summary.json, empty cells).
  bool estimated = false;
  Eigen::Vector3d force_err = Eigen::Vector3d::Zero();  // N
  Eigen::Vector3d torque_err = Eigen::Vector3d::Zero(); // N m
  std::string error_method;
};

// forces.csv: name,method,Fx,Fy,Fz,Tx,Ty,Tz (and the check columns when any force has one,
// then Fx_err..Tz_err when any force has an error estimate: appended, never reordered).
// Spread of a consistency check: the difference of force (and torque / radius) relative to
// the largest of |F| and |T| / radius; radius is the size of the surface.
double relative_difference(const ForceResult& a, const ForceResult& b, double radius);

std::string forces_csv(const std::vector<ForceResult>& forces);
nlohmann::ordered_json forces_json(const std::vector<ForceResult>& forces);
std::string describe_forces(const std::vector<ForceResult>& forces, bool per_metre);

} // namespace magfem
