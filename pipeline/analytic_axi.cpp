#include "pipeline/analytic_axi.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <variant>

#include "analytic/azimuthal_current_wrench.hpp"
#include "analytic/coaxial_coil_field.hpp"
#include "analytic/coil_closed_forms.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "mesh/region_map2d.hpp"
#include "mesh/region_overlap2d.hpp"
#include "pipeline/run2d.hpp"
#include "postproc/probe_rows2d.hpp"

namespace magfem {
namespace {

// One azimuthal current distribution: a coil's winding or one side of a magnet (a sheet of
// one turn carrying M times the magnet's length).
struct Source {
  int region = 0;
  CoaxialCoil geometry;
  double current = 0; // A per turn
  bool winding = false;
};

std::string region_field(int i) {
  return "regions[" + std::to_string(i) + "]";
}

const Rectangle& source_rectangle(const CaseSpec& spec, int i) {
  const auto* rect = std::get_if<Rectangle>(&spec.geometry2d.parts[i].shape);
  if (!rect || std::abs(rect->rotation) > 1e-12)
    throw InputError(spec.file, spec.regions[i].line, region_field(i) + ".shape",
                     "region " + spec.regions[i].name +
                         ": the analytic axisymmetric models take magnets and coils as "
                         "unrotated rectangles (cylinders, rings, thick coils)");
  return *rect;
}

// Whether a later part covers some of a source rectangle (a part with `overlap: replace`
// wins where it overlaps, so the meshed source would not be the whole rectangle the models
// assume).
void check_uncovered(const CaseSpec& spec, const std::vector<Source>& sources) {
  const auto& g = spec.geometry2d;
  const double chord = std::max(g.options.default_size, g.outer.radius / 20);
  std::unique_ptr<RegionMap2D> map;
  try {
    map = std::make_unique<RegionMap2D>(g, [chord](int, const Vec2&) { return chord; });
    check_region_overlaps2d(g, *map); // as the FE would refuse them
  } catch (const MeshError& e) {
    throw_mesh_error_2d(spec, e);
  }
  constexpr int n = 8; // cell centres per direction: a cover thinner than 1/8 can be missed
  int last = -1;
  for (const auto& s : sources) {
    if (s.region == last)
      continue; // a magnet's second sheet
    last = s.region;
    const Rectangle& rect = source_rectangle(spec, s.region);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) {
        const Vec2 p = rect.center + Vec2(rect.width * ((i + 0.5) / n - 0.5),
                                          rect.height * ((k + 0.5) / n - 0.5));
        const int at = map->region_of(p);
        if (at == s.region)
          continue;
        const int j = at >= 0 ? at : s.region;
        throw InputError(spec.file, spec.regions[j].line, region_field(j),
                         "region " + spec.regions[j].name + " covers part of region " +
                             spec.regions[s.region].name +
                             "; the analytic models need whole magnets and coils");
      }
  }
}

std::vector<Source> axi_sources(const CaseSpec& spec, std::vector<std::string>& notes) {
  if (spec.geometry2d.outer.kind != OuterKind::open)
    throw InputError(spec.file, spec.boundary_line, "boundary.type",
                     "the analytic axisymmetric models are for open boundaries; a Dirichlet "
                     "or Neumann boundary needs magfem solve");
  std::vector<Source> sources;
  for (std::size_t n = 0; n < spec.regions.size(); ++n) {
    const int i = static_cast<int>(n);
    const RegionSpec& region = spec.regions[n];
    const Material& mat = *region.material;
    const bool carries_current = region.carries_current();
    if (mat.is_magnet()) {
      const Magnetization& m = region.magnetization;
      if (m.pattern != Magnetization::Pattern::parallel || std::abs(m.direction.x()) > 1e-12)
        throw InputError(spec.file, region.line, region_field(i) + ".magnetization",
                         "region " + region.name +
                             ": the analytic axisymmetric models take magnets magnetized "
                             "along the axis only (parallel, angle 90 or -90)");
      if (mat.mu_r != 1.0)
        notes.push_back("region " + region.name + ": recoil mu_r " + std::to_string(mat.mu_r) +
                        " taken as 1 (the current-sheet model assumes mu_r = 1)");
      const Rectangle& r = source_rectangle(spec, i);
      const double r0 = std::max(0.0, r.center.x() - 0.5 * r.width);
      const double r1 = r.center.x() + 0.5 * r.width;
      const double z0 = r.center.y() - 0.5 * r.height, z1 = r.center.y() + 0.5 * r.height;
      const double sheet = m.sign * m.direction.y() * mat.B_r / mu0 * (z1 - z0); // M l, A
      sources.push_back({i, {r1, r1, z0, z1, 1.0}, sheet, false});
      if (r0 > 0)
        sources.push_back({i, {r0, r0, z0, z1, 1.0}, -sheet, false});
    } else if (mat.is_nonlinear() || mat.mu_r != 1.0) {
      throw InputError(spec.file, region.line, region_field(i) + ".material",
                       "region " + region.name + " is iron (material '" + mat.name +
                           "'); the analytic models have no iron: use magfem solve");
    } else if (carries_current) {
      const Rectangle& r = source_rectangle(spec, i);
      const double r0 = r.center.x() - 0.5 * r.width, r1 = r.center.x() + 0.5 * r.width;
      const double at = region.ampere_turns != 0 ? region.ampere_turns
                                                 : region.current_density * r.width * r.height;
      const double turns = region.turns != 0 ? region.turns : 1.0;
      sources.push_back({i,
                         {std::max(0.0, r0), r1, r.center.y() - 0.5 * r.height,
                          r.center.y() + 0.5 * r.height, turns},
                         at / turns,
                         true});
    }
  }
  if (sources.empty())
    throw InputError(spec.file, 0, "regions",
                     "no permanent magnets or coils: nothing for the analytic models to compute");
  check_uncovered(spec, sources);
  return sources;
}

// F_z (N) on `on` in the field of `by`: I_by I_on dM/dz by the pair integral, or, where the
// cross-sections touch (stacked magnets, a coil wound on a magnet: the pair integral refuses
// them), the Lorentz force on `on` in `by`'s field (integrable log singularity at the contact,
// z panels graded towards the ends). Coaxial, so the integrand is independent of phi.
double axial_force(const Source& on, const Source& by, const CoaxialCoilField& by_field) {
  try {
    return coaxial_axial_force(by.geometry, on.geometry, by.current, on.current);
  } catch (const std::invalid_argument&) {
    const PlacedCoil target{on.geometry}, source{by.geometry};
    WrenchQuadrature q;
    q.n_phi = 4;
    const auto b = [&](const Eigen::Vector3d& x) { return placed_coil_B(source, by_field, x); };
    return azimuthal_current_wrench(target, on.current, b, Eigen::Vector3d::Zero(), q).force.z();
  }
}

// Sum of F_z on the sources in `in` from those not in it.
double group_force(const std::vector<bool>& in, const Eigen::MatrixXd& pair) {
  double f = 0;
  for (Eigen::Index b = 0; b < pair.rows(); ++b)
    for (Eigen::Index a = 0; a < pair.cols(); ++a)
      if (in[b] && !in[a])
        f += pair(b, a);
  return f;
}

// The sources of the named regions.
std::vector<bool> of_regions(const CaseSpec& spec, const std::vector<Source>& sources,
                             const std::vector<std::string>& names) {
  std::vector<bool> in(sources.size(), false);
  for (std::size_t s = 0; s < sources.size(); ++s)
    in[s] =
        std::find(names.begin(), names.end(), spec.regions[sources[s].region].name) != names.end();
  return in;
}

// The sources inside a stress circle (a sphere about the axis); one it cuts is an error.
std::vector<bool> inside_circle(const CaseSpec& spec, const std::vector<Source>& sources,
                                const ForceSpec& f) {
  std::vector<bool> in(sources.size(), false);
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const auto& c = sources[s].geometry;
    int corners = 0;
    for (const double r : {c.r_inner, c.r_outer})
      for (const double z : {c.z_min, c.z_max})
        corners += std::hypot(r - f.center.x(), z - f.center.y()) < f.radius;
    if (corners != 0 && corners != 4)
      throw InputError(spec.file, f.line, "forces." + f.name,
                       "the stress circle cuts region " + spec.regions[sources[s].region].name);
    in[s] = corners == 4;
  }
  return in;
}

} // namespace

void run_axi_analytic(AnalyticRun& run) {
  const CaseSpec& spec = run.spec;
  const std::vector<Source> sources = axi_sources(spec, run.scene.notes);
  const std::size_t n = sources.size();
  std::vector<std::unique_ptr<CoaxialCoilField>> fields;
  int windings = 0, magnets = 0;
  for (std::size_t s = 0; s < n; ++s) {
    fields.push_back(std::make_unique<CoaxialCoilField>(sources[s].geometry, sources[s].current));
    windings += sources[s].winding;
    magnets += !sources[s].winding && (s == 0 || sources[s - 1].region != sources[s].region);
  }
  run.sources = std::to_string(windings) + " coil(s) by the exact thick-coil field, " +
                std::to_string(magnets) + " magnet(s) by their equivalent current sheets";

  for (const auto& probe : spec.probes) {
    const auto points = probe_points_2d(probe);
    std::vector<Eigen::Vector2d> b;
    for (const auto& x : points) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      for (const auto& f : fields) {
        const MeridianField h = f->H(x.x(), x.y());
        sum += mu0 * Eigen::Vector2d(h.h_rho, h.h_z);
      }
      b.push_back(sum);
    }
    run.n_points += points.size();
    run.probes.push_back(tabulate_probe_2d(probe, points, b, spec.length_unit, true));
  }

  // pair(b, a): F_z on source b from source a.
  Eigen::MatrixXd pair =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t b = 0; b < n; ++b)
    for (std::size_t a = 0; a < n; ++a)
      if (sources[a].region != sources[b].region)
        pair(b, a) = axial_force(sources[b], sources[a], *fields[a]);

  for (const auto& f : spec.forces) {
    std::vector<bool> in;
    ForceResult r;
    r.name = f.name;
    r.method = "analytic";
    switch (f.kind) {
    case ForceSpec::Kind::lorentz:
      in = of_regions(spec, sources, f.regions);
      r.method = "lorentz";
      break;
    case ForceSpec::Kind::contour:
      in = of_regions(spec, sources, {f.regions.front()});
      break;
    case ForceSpec::Kind::circle:
      in = inside_circle(spec, sources, f);
      break;
    default:
      continue; // planar or 3D kinds; the reader allows none of them in axi
    }
    r.force.z() = group_force(in, pair);
    run.forces.push_back(r);
  }

  // Coils (windings with turns): force, flux linkage (mutual inductances with every other
  // source, self-inductance), and the windings' inductance matrix.
  std::vector<std::size_t> coils;
  for (std::size_t s = 0; s < n; ++s)
    if (sources[s].winding && spec.regions[sources[s].region].turns != 0)
      coils.push_back(s);
  const auto nc = static_cast<Eigen::Index>(coils.size());
  run.inductance_H = Eigen::MatrixXd::Zero(nc, nc);
  bool matrix_known = true;
  for (Eigen::Index k = 0; k < nc; ++k) {
    const Source& c = sources[coils[k]];
    const RegionSpec& region = spec.regions[c.region];
    CoilResult r;
    r.name = region.name;
    r.turns = region.turns;
    r.current_A = region.current;
    std::vector<bool> self(n, false);
    self[coils[k]] = true;
    r.force_N.z() = group_force(self, pair);
    bool known = true;
    const double l_self = coaxial_coil_self_inductance(c.geometry);
    run.inductance_H(k, k) = l_self;
    r.flux_linkage_Wb = l_self * c.current;
    for (std::size_t a = 0; a < n; ++a) {
      if (a == coils[k])
        continue;
      try {
        const double m = coaxial_mutual_inductance(c.geometry, sources[a].geometry);
        r.flux_linkage_Wb += m * sources[a].current;
        const auto j = std::find(coils.begin(), coils.end(), a) - coils.begin();
        if (j < nc)
          run.inductance_H(k, j) = m;
      } catch (const std::invalid_argument&) {
        known = false; // touching cross-sections: the pair integral does not take them
        matrix_known = matrix_known && !sources[a].winding;
      }
    }
    if (!known)
      run.scene.notes.push_back("coil " + r.name +
                                ": flux linkage not computed (it touches another source)");
    run.coils.push_back(r);
    run.linkage_known.push_back(known);
  }
  if (!matrix_known) {
    run.inductance_H.resize(0, 0);
    run.scene.notes.push_back("inductance matrix not computed (coils touch)");
  }
}

} // namespace magfem
