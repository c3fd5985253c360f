#include "pipeline/force_results.hpp"

#include <algorithm>
#include <cstdio>

namespace magfem {
namespace {
nlohmann::ordered_json vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}
} // namespace

double relative_difference(const ForceResult& a, const ForceResult& b, double radius) {
  // A force and a torque are compared on one scale, the larger of |F| and |T| / radius
  // (the tangential force that makes T): a force that is zero by symmetry would otherwise
  // turn round-off into a large relative figure.
  const double f_scale = std::max(
      {a.force.norm(), b.force.norm(), a.torque.norm() / radius, b.torque.norm() / radius, 1e-300});
  return std::max((a.force - b.force).norm() / f_scale,
                  (a.torque - b.torque).norm() / (radius * f_scale));
}

std::string forces_csv(const std::vector<ForceResult>& forces) {
  const bool any_check =
      std::any_of(forces.begin(), forces.end(), [](const auto& f) { return f.checked; });
  const bool any_estimate =
      std::any_of(forces.begin(), forces.end(), [](const auto& f) { return f.estimated; });
  std::string out = "name,method,Fx,Fy,Fz,Tx,Ty,Tz";
  if (any_check)
    out += ",check_Fx,check_Fy,check_Fz,check_Tx,check_Ty,check_Tz,check_rel_diff";
  if (any_estimate)
    out += ",Fx_err,Fy_err,Fz_err,Tx_err,Ty_err,Tz_err";
  out += "\n";
  char buf[512];
  for (const auto& f : forces) {
    std::snprintf(buf, sizeof buf, "%s,%s,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g", f.name.c_str(),
                  f.method.c_str(), f.force.x(), f.force.y(), f.force.z(), f.torque.x(),
                  f.torque.y(), f.torque.z());
    out += buf;
    if (any_check) {
      if (f.checked)
        std::snprintf(buf, sizeof buf, ",%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.6g",
                      f.check_force.x(), f.check_force.y(), f.check_force.z(), f.check_torque.x(),
                      f.check_torque.y(), f.check_torque.z(), f.check_relative_difference);
      else
        std::snprintf(buf, sizeof buf, ",,,,,,,");
      out += buf;
    }
    if (any_estimate) {
      if (f.estimated)
        std::snprintf(buf, sizeof buf, ",%.4g,%.4g,%.4g,%.4g,%.4g,%.4g", f.force_err.x(),
                      f.force_err.y(), f.force_err.z(), f.torque_err.x(), f.torque_err.y(),
                      f.torque_err.z());
      else
        std::snprintf(buf, sizeof buf, ",,,,,,");
      out += buf;
    }
    out += "\n";
  }
  return out;
}

nlohmann::ordered_json forces_json(const std::vector<ForceResult>& forces) {
  auto j = nlohmann::ordered_json::array();
  for (const auto& f : forces) {
    nlohmann::ordered_json e;
    e["name"] = f.name;
    e["method"] = f.method;
    e["force_N"] = vec(f.force);
    e["torque_Nm"] = vec(f.torque);
    if (f.checked) {
      e["check_force_N"] = vec(f.check_force);
      e["check_torque_Nm"] = vec(f.check_torque);
      e["check_relative_difference"] = f.check_relative_difference;
    }
    if (f.estimated)
      e["error_estimate"] = {{"force_N", vec(f.force_err)},
                             {"torque_Nm", vec(f.torque_err)},
                             {"method", f.error_method}};
    j.push_back(e);
  }
  return j;
}

std::string describe_forces(const std::vector<ForceResult>& forces, bool per_metre) {
  std::string out;
  char buf[512];
  const char* fu = per_metre ? "N/m" : "N";
  const char* tu = per_metre ? "N m/m" : "N m";
  for (const auto& f : forces) {
    std::snprintf(buf, sizeof buf,
                  "force    %-12s %-14s F = (%.6g, %.6g, %.6g) %s, T = (%.6g, %.6g, %.6g) %s",
                  f.name.c_str(), f.method.c_str(), f.force.x(), f.force.y(), f.force.z(), fu,
                  f.torque.x(), f.torque.y(), f.torque.z(), tu);
    out += buf;
    if (f.checked) {
      std::snprintf(buf, sizeof buf, "; second surface differs by %.3g %%",
                    100 * f.check_relative_difference);
      out += buf;
    }
    if (f.estimated) {
      std::snprintf(buf, sizeof buf, "; estimated error |F| %.2g %s, |T| %.2g %s",
                    f.force_err.norm(), fu, f.torque_err.norm(), tu);
      out += buf;
    }
    out += "\n";
  }
  return out;
}

} // namespace magfem
