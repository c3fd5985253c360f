#include "pipeline/symmetry2d.hpp"

#include <algorithm>
#include <map>

#include "casefile/symmetry_check2d.hpp"
#include "pipeline/mirror_image_regions.hpp"
#include "pipeline/run2d.hpp"
#include "postproc/lorentz2d.hpp"
#include "solver/triangle_lagrange.hpp"

namespace magfem {
namespace {

// A reflection combination: bit k set = reflected about plane k.
struct Image {
  Eigen::Matrix3d r3 = Eigen::Matrix3d::Identity(); // on 3D vectors (forces, torques)
  double det = 1;
  int part = 0; // the part the meshed part's image is
};

Image image_of(const CaseSpec& spec, const std::vector<std::vector<int>>& mirrors, unsigned g,
               int part) {
  Image im;
  im.part = part;
  const auto& planes = spec.geometry2d.planes;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    if (!(g >> k & 1u))
      continue;
    // Axisymmetric: the r-z plane's y axis is the 3D z axis.
    const int axis3 = spec.axisymmetric() ? 2 : planes[k].axis;
    im.r3(axis3, axis3) = -im.r3(axis3, axis3);
    im.det = -im.det;
    if (im.part >= 0)
      im.part = mirrors[k][std::size_t(im.part)];
  }
  return im;
}

// A region id of the whole device from the one of the folded point (parts through the
// mirror tables, air and shell as they are).
int region_in_whole(const std::vector<std::vector<int>>& mirrors, unsigned g, int region) {
  for (std::size_t k = 0; k < mirrors.size(); ++k)
    if ((g >> k & 1u) && region >= 0)
      region = mirrors[k][std::size_t(region)];
  return region;
}

void add_piece(SectionFlux& out, std::map<int, SectionPart>& parts, const SectionFlux& piece,
               double sign, const std::vector<std::vector<int>>& mirrors, unsigned g) {
  out.nominal_area_m2 += piece.nominal_area_m2;
  for (const SectionPart& p : piece.parts) {
    SectionPart& q = parts[region_in_whole(mirrors, g, p.region)];
    q.region = region_in_whole(mirrors, g, p.region);
    q.area_m2 += p.area_m2;
    q.flux_Wb += sign * p.flux_Wb;
    q.abs_B_Tm2 += p.abs_B_Tm2;
  }
}

} // namespace

std::vector<double> whole_part_areas(const CaseSpec& spec, const Mesh2D& mesh) {
  std::vector<double> area(spec.regions.size(), 0.0);
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t) {
    const int p = mesh.triangle_part[t];
    if (p < 0)
      continue;
    const auto& tri = mesh.triangles[t];
    area[std::size_t(p)] +=
        TriangleGeometry::of(mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]).area;
  }
  if (!spec.geometry2d.planes.empty()) {
    const std::vector<double> factor = region_symmetry_factors_2d(spec);
    for (std::size_t i = 0; i < area.size(); ++i)
      area[i] *= factor[i];
    // A part wholly beyond a plane is not meshed: its area is its image's.
    const std::vector<int> images = share_images_2d(spec);
    for (std::size_t i = 0; i < area.size(); ++i)
      if (images[i] >= 0)
        area[i] = area[std::size_t(images[i])];
  }
  return area;
}

void scale_to_whole_device_2d(Run2D& run) {
  const auto& planes = run.spec.geometry2d.planes;
  if (planes.empty())
    return;
  const double factor = symmetry_factor_2d(planes);
  const std::vector<double> per_part = region_symmetry_factors_2d(run.spec);
  run.energy.total_J_per_m *= factor;
  for (auto& r : run.energy.regions) {
    const double f = r.part >= 0 ? per_part[std::size_t(r.part)] : factor; // air, shell
    r.energy_J_per_m *= f;
    r.area_m2 *= f;
  }
  fill_mirror_image_regions(run.energy.regions, share_images_2d(run.spec));
  // The estimate's relative errors are ratios of two energies scaled alike.
  run.error_estimate.total_eta2 *= factor;
}

SectionFlux integrate_section_whole_2d(const Field2D& field, const SectionSpec& section,
                                       double depth, const CaseSpec& spec) {
  const auto& planes = spec.geometry2d.planes;
  if (planes.empty())
    return integrate_section_2d(field, section, depth);
  const std::vector<std::vector<int>> mirrors = mirror_parts_2d(spec);
  const Vec2 a = section.start, d = section.end - section.start;
  std::vector<double> cuts{0.0, 1.0};
  for (const SymmetryPlane2D& p : planes)
    if (const double t = -a[p.axis] / d[p.axis]; d[p.axis] != 0 && t > 0 && t < 1)
      cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  SectionFlux out;
  out.name = section.name;
  std::map<int, SectionPart> parts;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    SectionSpec piece = section;
    piece.start = a + cuts[k] * d;
    piece.end = a + cuts[k + 1] * d;
    for (const SymmetryPlane2D& p : planes) // the cut points exactly on their plane
      for (Vec2* x : {&piece.start, &piece.end})
        if (std::abs((*x)[p.axis]) <= 1e-12 * d.norm())
          (*x)[p.axis] = 0;
    const Vec2 mid = 0.5 * (piece.start + piece.end);
    unsigned g = 0;
    double sign = 1; // the flux through a piece read at its image: A's sign (a_sign)
    for (std::size_t q = 0; q < planes.size(); ++q) {
      const int ax = planes[q].axis;
      if (mid[ax] >= 0)
        continue;
      g |= 1u << q;
      piece.start[ax] = -piece.start[ax];
      piece.end[ax] = -piece.end[ax];
      sign *= planes[q].field == SymmetryField::normal ? 1 : -1;
    }
    // A piece along a plane is counted by the triangle on its +n side (section_flux2d): turn
    // it so that side is the model's.
    for (const SymmetryPlane2D& p : planes) {
      const Vec2 t = piece.end - piece.start;
      if (piece.start[p.axis] == 0 && piece.end[p.axis] == 0 && Vec2(-t.y(), t.x())[p.axis] < 0) {
        std::swap(piece.start, piece.end);
        sign = -sign;
      }
    }
    add_piece(out, parts, integrate_section_2d(field, piece, depth), sign, mirrors, g);
  }
  finish_section_2d(out, parts);
  return out;
}

ForceTorque lorentz_force_whole_2d(const Field2D& field, const std::vector<int>& parts,
                                   const Eigen::Vector2d& torque_point, const CaseSpec& spec) {
  const auto& planes = spec.geometry2d.planes;
  if (planes.empty())
    return lorentz_force_2d(field, parts, torque_point);
  const std::vector<std::vector<int>> mirrors = mirror_parts_2d(spec);
  // Every meshed part's force and torque about the origin, carried to each of its images:
  // the force density at R x is R f(x) whichever the condition (it is quadratic in the
  // sources), a torque (a pseudovector) turns with det(R) R.
  ForceTorque total;
  for (std::size_t q = 0; q < spec.regions.size(); ++q) {
    const ForceTorque ft = lorentz_force_2d(field, {int(q)}, Eigen::Vector2d::Zero());
    for (unsigned g = 0; g < (1u << planes.size()); ++g) {
      const Image im = image_of(spec, mirrors, g, int(q));
      if (std::find(parts.begin(), parts.end(), im.part) == parts.end())
        continue;
      total.force += im.r3 * ft.force;
      total.torque += im.det * im.r3 * ft.torque;
    }
  }
  total.torque -= Eigen::Vector3d(torque_point.x(), torque_point.y(), 0).cross(total.force);
  if (spec.axisymmetric())
    total.torque.setZero();
  return total;
}

void add_symmetry_json_2d(nlohmann::ordered_json& j, const CaseSpec& spec) {
  const auto& planes = spec.geometry2d.planes;
  if (planes.empty())
    return;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& p : planes)
    list.push_back(
        {{"plane", plane_name_2d(p, spec.axisymmetric())}, {"field", field_name(p.field)}});
  j["symmetry"] = list;
  j["symmetry_factor"] = symmetry_factor_2d(planes);
}

} // namespace magfem
