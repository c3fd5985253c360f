#include "pipeline/analytic_scene.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <variant>

#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "mesh/part_overlap3d.hpp"

namespace magfem {
namespace {

// Materials this permeable are treated as infinitely permeable (the thesis's FEA used 4000
// for its "infinitely permeable" boundary).
constexpr double permeable_threshold = 1000.0;

double max_extent(const AnalyticMagnet& m) {
  // Distance of the farthest point of the magnet from the origin (bounding sphere).
  const double local = std::visit(
      [](const auto& s) -> double {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SphericalSegment>)
          return s.r_outer;
        else if constexpr (std::is_same_v<T, Cylinder>)
          return std::hypot(s.r_outer, s.height);
        else if constexpr (std::is_same_v<T, TriangleSurface>)
          return std::numeric_limits<double>::infinity(); // never a magnet here (refused)
        else
          return 0.5 * s.size.norm();
      },
      m.shape);
  return m.placement.translation.norm() + local;
}

// A spherical segment about the origin that lies wholly outside radius r (the shell of the
// spherical actuator around its back-iron core).
bool shell_outside(const AnalyticMagnet& m, double r) {
  const auto* seg = std::get_if<SphericalSegment>(&m.shape);
  return seg && m.placement.translation.norm() < 1e-12 && seg->r_inner >= r - 1e-12;
}

// A sphere containing the part (centre, radius), for skipping pairs that cannot overlap.
std::pair<Vec3, double> bounding_sphere(const Part3D& part) {
  return std::visit(
      [&](const auto& s) -> std::pair<Vec3, double> {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, SphericalSegment>)
          return {part.placement.translation, s.r_outer};
        else if constexpr (std::is_same_v<T, Cylinder>)
          return {part.placement.to_global(Vec3(0, 0, 0.5 * s.height)),
                  std::hypot(s.r_outer, 0.5 * s.height)};
        else if constexpr (std::is_same_v<T, TriangleSurface>) {
          double r = 0;
          for (const Vec3& x : s.points)
            r = std::max(r, x.norm());
          return {part.placement.translation, r};
        } else
          return {part.placement.translation, 0.5 * s.size.norm()};
      },
      part.shape);
}

// The charge model superposes magnets: two that share volume would be added up without
// complaint (the mesher refuses them in FE). Parts that only touch are fine. Pairs whose
// bounding spheres are apart are skipped (a 180-cylinder array has 16,000 pairs).
void reject_overlaps(const CaseSpec& spec) {
  const auto& parts = spec.geometry3d.parts;
  std::vector<std::pair<Vec3, double>> spheres;
  for (const auto& part : parts)
    spheres.push_back(bounding_sphere(part));
  for (std::size_t j = 0; j < parts.size(); ++j) {
    if (is_air(*spec.regions[j].material))
      continue;
    for (std::size_t i = 0; i < j; ++i) {
      if (is_air(*spec.regions[i].material))
        continue;
      const double apart = (spheres[i].first - spheres[j].first).norm();
      if (apart > 1.001 * (spheres[i].second + spheres[j].second))
        continue;
      auto x = overlap_point(parts[i], parts[j], 12);
      if (!x)
        x = overlap_point(parts[j], parts[i], 12);
      if (!x)
        continue;
      const Vec3 p = *x / spec.length_unit;
      char where[96];
      std::snprintf(where, sizeof where, "(%.3g, %.3g, %.3g) %s", p.x(), p.y(), p.z(),
                    spec.unit_name.c_str());
      throw InputError(spec.file, spec.regions[j].line, "regions[" + std::to_string(j) + "]",
                       "region " + parts[j].name + " overlaps region " + parts[i].name +
                           " (e.g. at " + where + "); parts must not share volume");
    }
  }
}

} // namespace

bool is_air(const Material& m) {
  return m.kind == MaterialKind::linear && m.mu_r == 1.0;
}

bool full_sphere_at_origin(const Part3D& part) {
  const auto* seg = std::get_if<SphericalSegment>(&part.shape);
  return seg && seg->theta_min <= 1e-12 && seg->theta_max >= pi - 1e-12 &&
         seg->phi_max - seg->phi_min >= 2 * pi - 1e-12 && part.placement.translation.norm() < 1e-12;
}

AnalyticScene analytic_scene(const CaseSpec& spec) {
  if (spec.dimension != 3)
    throw InputError(spec.file, 0, "dimension",
                     "the analytic models are 3D; 2D closed forms are compared in the tests");
  AnalyticScene scene;
  std::vector<std::pair<const Part3D*, std::size_t>> permeable; // part, region index
  for (std::size_t i = 0; i < spec.regions.size(); ++i) {
    const auto& part = spec.geometry3d.parts[i];
    const auto& region = spec.regions[i];
    const Material& mat = *region.material;
    auto reject = [&](const std::string& why) {
      throw InputError(spec.file, region.line, "regions[" + std::to_string(i) + "].material",
                       "region " + region.name +
                           " is not representable by the analytic models: " + why);
    };
    if (is_air(mat))
      continue;
    if (const auto* surface = std::get_if<TriangleSurface>(&part.shape))
      throw InputError(spec.file, region.line, "regions[" + std::to_string(i) + "].shape",
                       "region " + region.name + " (" + surface->file +
                           ") is a triangulated surface: the analytic models take spherical "
                           "segments, cylinders and boxes only; solve the case by finite "
                           "elements (magfem solve)");
    if (mat.is_magnet()) {
      if (mat.mu_r != 1.0)
        scene.notes.push_back("region " + region.name + ": recoil mu_r " +
                              std::to_string(mat.mu_r) +
                              " taken as 1 (the charge model assumes mu_r = 1)");
      scene.magnets.push_back(
          {part.shape, part.placement, region.magnetization, mat.B_r, region.name});
    } else if (mat.is_nonlinear()) {
      reject("nonlinear material '" + mat.name + "'");
    } else if (mat.mu_r >= permeable_threshold && full_sphere_at_origin(part)) {
      permeable.emplace_back(&part, i);
    } else {
      reject("linear material '" + mat.name + "' with mu_r " + std::to_string(mat.mu_r) +
             " (only mu_r = 1, or mu_r >= 1000 as full spheres/shells about the origin)");
    }
  }
  reject_overlaps(spec);
  double extent = 0;
  for (const auto& m : scene.magnets)
    extent = std::max(extent, max_extent(m));
  for (const auto& [part, index] : permeable) {
    const RegionSpec* region = &spec.regions[index];
    const auto& seg = std::get<SphericalSegment>(part->shape);
    if (extent <= seg.r_inner + 1e-12) {
      scene.spheres.push_back({Eigen::Vector3d::Zero(), seg.r_inner, true});
    } else {
      // The magnets must all lie outside the iron ball/shell: it acts as an inner core.
      for (const auto& m : scene.magnets)
        if (m.placement.translation.norm() < seg.r_outer && !shell_outside(m, seg.r_outer))
          throw InputError(spec.file, region->line, "regions[" + std::to_string(index) + "]",
                           "not representable: permeable shell " + region->name +
                               " between magnets");
      scene.spheres.push_back({Eigen::Vector3d::Zero(), seg.r_outer, false});
    }
    scene.notes.push_back("region " + region->name + ": mu_r " +
                          std::to_string(region->material->mu_r) +
                          " treated as infinitely permeable (imaging)");
  }
  if (spec.geometry3d.outer.kind == OuterKind3D::dirichlet)
    scene.spheres.push_back({Eigen::Vector3d::Zero(), spec.geometry3d.outer.radius, true});
  else if (spec.geometry3d.outer.kind == OuterKind3D::neumann)
    throw InputError(spec.file, spec.boundary_line, "boundary.type",
                     "a Neumann (flux-tight) sphere is not representable by the analytic models");
  if (scene.magnets.empty() && spec.geometry3d.coils.empty())
    throw InputError(spec.file, 0, "regions",
                     "no permanent magnets or coils: nothing for the analytic models to compute");
  return scene;
}

} // namespace magfem
