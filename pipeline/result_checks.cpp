#include "pipeline/result_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "pipeline/force_results.hpp"
#include "core/input_error.hpp"

namespace magfem {
namespace {

// A magnet, soft iron or linear permeable region: the stress tensor must not cross it.
// Air and current-only regions (coils) are mu0 and the tensor stays valid there.
const char* field_source_kind(const RegionSpec& r) {
  if (r.material->kind == MaterialKind::magnet)
    return "magnet";
  if (r.material->kind == MaterialKind::soft)
    return "iron";
  if (r.material->mu_r != 1.0)
    return "permeable";
  return nullptr;
}

std::string length_text(double metres, const CaseSpec& spec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g %s", metres / spec.length_unit, spec.unit_name.c_str());
  return buf;
}

// Signed distances (negative inside) of a surface; the element is cut when its vertices lie
// on both sides by more than round-off (vertices on the surface cut nothing).
struct Surface {
  std::string description;
  std::function<double(const Eigen::Vector3d&)> distance;
  double tol = 0;
  // A band is a volume, not a surface: any vertex strictly inside it is a cut.
  bool volume = false;
};

std::vector<Surface> surfaces_of(const ForceSpec& f, const CaseSpec& spec) {
  std::vector<Surface> out;
  const Eigen::Vector3d c = f.center;
  auto sphere = [&](double r, const char* kind) {
    out.push_back({std::string(kind) + " of radius " + length_text(r, spec),
                   [c, r, planar = spec.dimension == 2](const Eigen::Vector3d& x) {
                     Eigen::Vector3d d = x - c;
                     if (planar)
                       d.z() = 0;
                     return d.norm() - r;
                   },
                   1e-9 * r});
  };
  auto box = [&](const Eigen::Vector3d& size) {
    const Eigen::Vector3d half = 0.5 * size;
    out.push_back({"box " + length_text(size.x(), spec) + " x " + length_text(size.y(), spec) +
                       " x " + length_text(size.z(), spec),
                   [c, half](const Eigen::Vector3d& x) {
                     const Eigen::Vector3d q = (x - c).cwiseAbs() - half;
                     return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
                   },
                   1e-9 * size.norm()});
  };
  switch (f.kind) {
  case ForceSpec::Kind::circle:
  case ForceSpec::Kind::sphere:
    for (double r : {f.radius, f.check_radius})
      if (r > 0)
        sphere(r, f.kind == ForceSpec::Kind::circle ? "circle" : "sphere");
    break;
  case ForceSpec::Kind::band: {
    const double ri = f.r_inner, ro = f.r_outer;
    out.push_back({"band " + length_text(ri, spec) + " to " + length_text(ro, spec),
                   [c, ri, ro](const Eigen::Vector3d& x) {
                     const double r = Eigen::Vector2d(x.x() - c.x(), x.y() - c.y()).norm();
                     return std::max(ri - r, r - ro); // negative inside the band
                   },
                   1e-9 * ro, true});
    break;
  }
  case ForceSpec::Kind::box:
    box(f.size);
    if (f.check_size.norm() > 0)
      box(f.check_size);
    break;
  default:
    break;
  }
  return out;
}

template <class Element, class Point>
void check_cuts(const CaseSpec& spec, const std::vector<Point>& nodes,
                const std::vector<Element>& elements, const std::vector<int>& element_part) {
  for (std::size_t i = 0; i < spec.forces.size(); ++i) {
    const ForceSpec& f = spec.forces[i];
    for (const Surface& s : surfaces_of(f, spec))
      for (std::size_t e = 0; e < elements.size(); ++e) {
        const int part = element_part[e];
        if (part < 0 || !field_source_kind(spec.regions[part]))
          continue;
        bool below = false, above = false;
        for (const int v : elements[e]) {
          Eigen::Vector3d x = Eigen::Vector3d::Zero();
          x.head(nodes[v].size()) = nodes[v];
          const double d = s.distance(x);
          below = below || d < -s.tol;
          above = above || d > s.tol;
        }
        if (s.volume ? below : below && above)
          throw InputError(spec.file, f.line, "forces." + f.name,
                           "force '" + f.name + "': its " + s.description + " cuts " +
                               field_source_kind(spec.regions[part]) + " region '" +
                               spec.regions[part].name +
                               "'; the stress tensor holds in air only, so the force and "
                               "torque would be wrong: put the surface in the air around it");
      }
  }
}

} // namespace

void check_finite(const Eigen::VectorXd& values, const std::string& what) {
  if (!values.allFinite())
    throw SolveError("the " + what +
                     " contains NaN or Inf (a material or source value out of range?); "
                     "nothing was written");
}

void check_finite(const std::vector<Eigen::Vector3d>& values, const std::string& what) {
  for (const auto& v : values)
    if (!v.allFinite())
      throw SolveError("the " + what + " contains NaN or Inf; nothing was written");
}

void check_finite(double value, const std::string& what) {
  if (!std::isfinite(value))
    throw SolveError("the " + what + " is NaN or Inf; nothing was written");
}

void check_forces_finite(const std::vector<ForceResult>& forces) {
  for (const auto& f : forces)
    if (!f.force.allFinite() || !f.torque.allFinite())
      throw SolveError("force '" + f.name + "' is NaN or Inf; nothing was written");
}

std::vector<std::string> bh_extrapolation_warnings(const std::vector<RegionSpec>& regions,
                                                   const std::vector<double>& peak_B_T) {
  std::vector<std::string> warnings;
  for (std::size_t i = 0; i < regions.size() && i < peak_B_T.size(); ++i) {
    const Material& m = *regions[i].material;
    if (!m.is_nonlinear() || !m.curve)
      continue;
    const double last = m.curve->b_table().back();
    if (peak_B_T[i] <= last)
      continue;
    char buf[320];
    std::snprintf(buf, sizeof buf,
                  "region '%s': B reaches %.4g T, beyond the last point of the B-H table of "
                  "'%s' (%.4g T); above it the curve is extrapolated with slope mu0",
                  regions[i].name.c_str(), peak_B_T[i], m.name.c_str(), last);
    warnings.push_back(buf);
  }
  return warnings;
}

void check_stress_surfaces_2d(const CaseSpec& spec, const Mesh2D& mesh) {
  check_cuts(spec, mesh.nodes, mesh.triangles, mesh.triangle_part);
}

void check_stress_surfaces_3d(const CaseSpec& spec, const Mesh3D& mesh) {
  check_cuts(spec, mesh.nodes, mesh.tets, mesh.tet_part);
}

} // namespace magfem
