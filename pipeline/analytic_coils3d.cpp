#include "pipeline/analytic_coils3d.hpp"

#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>
#include <variant>

#include "analytic/torque_constants.hpp"
#include "core/constants.hpp"
#include "core/input_error.hpp"
#include "mesh/part_overlap3d.hpp"
#include "analytic/analytic_force.hpp"
#include "analytic/azimuthal_current_wrench.hpp"
#include "analytic/coil_closed_forms.hpp"
#include "analytic/pair_interaction.hpp"

namespace magfem {
namespace {

using Batch = std::function<std::vector<Vec3>(const std::vector<Vec3>&)>;

// B (T) of some magnets (charge model, mu_r 1) and some coils at their currents.
Batch field_of(const std::vector<AnalyticMagnet>& magnets, std::vector<const CoilField*> coils,
               const ChargeModelOptions& options) {
  std::shared_ptr<const ChargeModel> model;
  if (!magnets.empty())
    model = std::make_shared<ChargeModel>(magnets, std::vector<PermeableSphere>{}, options);
  return [model, coils](const std::vector<Vec3>& x) {
    std::vector<Vec3> b = model ? model->B(x) : std::vector<Vec3>(x.size(), Vec3::Zero());
    for (std::size_t i = 0; i < x.size(); ++i)
      for (const CoilField* c : coils)
        b[i] += mu0 * c->H(x[i]);
    return b;
  };
}

PlacedCoil placed_solenoid(const Coil3D& c, const Solenoid& s) {
  return {{s.r_inner, s.r_outer, -0.5 * s.length, 0.5 * s.length, c.turns},
          c.placement.translation,
          c.placement.rotation.col(2)};
}

// Lorentz force and torque about `pivot` on a coil in the field `b`.
ForceTorque coil_wrench(const CoilField& field, const Batch& b, const Vec3& pivot) {
  const Coil3D& c = field.coil();
  if (const auto* s = std::get_if<Solenoid>(&c.shape)) {
    // The wrench asks for B point by point; record its points once and replay their values
    // from one batch evaluation (the charge model threads over a batch).
    const PlacedCoil placed = placed_solenoid(c, *s);
    std::vector<Vec3> points;
    azimuthal_current_wrench(
        placed, c.current,
        [&](const Vec3& x) {
          points.push_back(x);
          return Vec3::Zero().eval();
        },
        pivot);
    const std::vector<Vec3> values = b(points);
    std::size_t next = 0;
    const Wrench w = azimuthal_current_wrench(
        placed, c.current, [&](const Vec3&) { return values.at(next++); }, pivot);
    return {w.force, w.torque};
  }
  const auto rule = torque_quadrature(field, CoilRule{});
  std::vector<Vec3> points;
  for (const auto& q : rule)
    points.push_back(q.x);
  const std::vector<Vec3> values = b(points);
  ForceTorque out;
  for (std::size_t i = 0; i < rule.size(); ++i) {
    const Vec3 f = rule[i].weight * c.current * rule[i].j_per_ampere.cross(values[i]);
    out.force += f;
    out.torque += (rule[i].x - pivot).cross(f);
  }
  return out;
}

bool inside_surface(const ForceSpec& f, const Vec3& x) {
  const Vec3 d = x - f.center;
  if (f.kind == ForceSpec::Kind::sphere)
    return d.norm() < f.radius;
  return (d.cwiseAbs() - 0.5 * f.size).maxCoeff() < 0;
}

bool magnet_inside(const ForceSpec& f, const AnalyticMagnet& m) {
  Part3D surface;
  surface.placement.translation = f.center;
  if (f.kind == ForceSpec::Kind::sphere)
    surface.shape = SphericalSegment{0, f.radius, 0, pi, 0, 2 * pi};
  else
    surface.shape = Box{f.size};
  Part3D magnet;
  magnet.shape = m.shape;
  magnet.placement = m.placement;
  return overlap_point(magnet, surface, 12) || overlap_point(surface, magnet, 12);
}

// A source on a coil's axis, in the coil's frame (z along its axis from its centre).
struct AxialSource {
  CoaxialCoil geometry;
  double current = 0; // per turn, signed for circulation about the coil's axis
};

struct Axis {
  Vec3 origin, direction;
  // Position along the axis of a point on it, or nothing off the axis.
  std::optional<double> along(const Vec3& x) const {
    const Vec3 d = x - origin;
    const double t = d.dot(direction);
    if ((d - t * direction).norm() > 1e-9)
      return std::nullopt;
    return t;
  }
  bool parallel(const Vec3& a) const { return a.cross(direction).norm() < 1e-9; }
};

std::optional<AxialSource> coil_on_axis(const Axis& axis, const Coil3D& c) {
  const auto* s = std::get_if<Solenoid>(&c.shape);
  const Vec3 a = c.placement.rotation.col(2);
  const auto t = axis.along(c.placement.translation);
  if (!s || !t || !axis.parallel(a))
    return std::nullopt;
  return AxialSource{{s->r_inner, s->r_outer, *t - 0.5 * s->length, *t + 0.5 * s->length, c.turns},
                     a.dot(axis.direction) * c.current};
}

// A cylinder magnet of mu_r 1 magnetized along the axis: its sheets (M l on the outer side,
// -M l on the inner side).
std::optional<std::vector<AxialSource>> magnet_on_axis(const Axis& axis, const AnalyticMagnet& m) {
  const auto* cyl = std::get_if<Cylinder>(&m.shape);
  const Vec3 a = m.placement.rotation.col(2);
  const auto t0 = axis.along(m.placement.translation);
  const Magnetization& mag = m.magnetization;
  if (!cyl || !t0 || !axis.parallel(a) || mag.pattern != Magnetization::Pattern::parallel ||
      !axis.parallel(mag.direction))
    return std::nullopt;
  const double t1 = *t0 + a.dot(axis.direction) * cyl->height;
  const double z0 = std::min(*t0, t1), z1 = std::max(*t0, t1);
  const double sheet = mag.sign * mag.direction.dot(axis.direction) * m.B_r / mu0 * (z1 - z0);
  std::vector<AxialSource> out{{{cyl->r_outer, cyl->r_outer, z0, z1, 1.0}, sheet}};
  if (cyl->r_inner > 0)
    out.push_back({{cyl->r_inner, cyl->r_inner, z0, z1, 1.0}, -sheet});
  return out;
}

// Flux linkage of coil k (and its row of mutual inductances with the other coils), or
// nothing when some source is not on its axis or touches it.
std::optional<double> axial_linkage(const std::vector<Coil3D>& coils,
                                    const std::vector<AnalyticMagnet>& magnets, std::size_t k,
                                    Eigen::MatrixXd& inductance) {
  const Coil3D& c = coils[k];
  const Axis axis{c.placement.translation, c.placement.rotation.col(2)};
  const auto self = coil_on_axis(axis, c);
  if (!self)
    return std::nullopt;
  const auto ki = static_cast<Eigen::Index>(k);
  try {
    inductance(ki, ki) = coaxial_coil_self_inductance(self->geometry);
    double linkage = inductance(ki, ki) * c.current;
    for (std::size_t j = 0; j < coils.size(); ++j) {
      if (j == k)
        continue;
      const auto other = coil_on_axis(axis, coils[j]);
      if (!other)
        return std::nullopt;
      const double m = coaxial_mutual_inductance(self->geometry, other->geometry);
      // Per ampere of coil j's own current, which circulates about its own axis.
      const double orientation = coils[j].placement.rotation.col(2).dot(axis.direction);
      inductance(ki, static_cast<Eigen::Index>(j)) = orientation * m;
      linkage += m * other->current;
    }
    for (const auto& magnet : magnets) {
      const auto sheets = magnet_on_axis(axis, magnet);
      if (!sheets)
        return std::nullopt;
      for (const auto& s : *sheets)
        linkage += coaxial_mutual_inductance(self->geometry, s.geometry) * s.current;
    }
    return linkage;
  } catch (const std::invalid_argument&) {
    return std::nullopt; // touching cross-sections
  }
}

} // namespace

void analytic_coils_3d(AnalyticRun& run, const ChargeModelOptions& field_options) {
  const CaseSpec& spec = run.spec;
  const auto& coils = spec.geometry3d.coils;
  const auto& magnets = run.scene.magnets;
  std::vector<std::unique_ptr<CoilField>> fields;
  for (const auto& c : coils)
    fields.push_back(std::make_unique<CoilField>(c));
  auto other_coils = [&](auto keep) {
    std::vector<const CoilField*> out;
    for (std::size_t j = 0; j < coils.size(); ++j)
      if (keep(j))
        out.push_back(fields[j].get());
    return out;
  };

  const auto nc = static_cast<Eigen::Index>(coils.size());
  Eigen::MatrixXd inductance = Eigen::MatrixXd::Zero(nc, nc);
  bool matrix_known = true;
  for (std::size_t k = 0; k < coils.size(); ++k) {
    const Coil3D& c = coils[k];
    CoilResult r;
    r.name = c.name;
    r.turns = c.turns;
    r.current_A = c.current;
    r.resistance_ohm = fields[k]->resistance();
    r.power_W = r.resistance_ohm * c.current * c.current;
    const Batch b =
        field_of(magnets, other_coils([k](std::size_t j) { return j != k; }), field_options);
    const ForceTorque ft = coil_wrench(*fields[k], b, Vec3::Zero());
    r.force_N = ft.force;
    r.torque_Nm = ft.torque;
    const auto linkage = axial_linkage(coils, magnets, k, inductance);
    run.linkage_known.push_back(linkage.has_value());
    if (linkage)
      r.flux_linkage_Wb = *linkage;
    else
      run.scene.notes.push_back("coil " + c.name +
                                ": flux linkage not computed (the closed forms need solenoids "
                                "and axial cylinder magnets on its axis, not touching it)");
    matrix_known = matrix_known && linkage.has_value();
    run.coils.push_back(r);
  }
  if (matrix_known)
    run.inductance_H = inductance;

  for (const auto& f : spec.forces) {
    ForceResult r;
    r.name = f.name;
    if (f.kind == ForceSpec::Kind::lorentz) {
      // Moved from the origin to the spec's torque point.
      r.method = "lorentz";
      for (const auto& name : f.regions)
        for (std::size_t k = 0; k < coils.size(); ++k)
          if (coils[k].name == name) {
            r.force += run.coils[k].force_N;
            r.torque += run.coils[k].torque_Nm - f.torque_point.cross(run.coils[k].force_N);
          }
      run.forces.push_back(r);
      continue;
    }
    if (f.kind != ForceSpec::Kind::sphere && f.kind != ForceSpec::Kind::box)
      continue;
    r.method = "analytic";
    std::vector<bool> coil_in(coils.size());
    for (std::size_t k = 0; k < coils.size(); ++k) {
      int inside = 0, total = 0;
      for (const auto& q : fields[k]->volume_quadrature(2)) {
        inside += inside_surface(f, q.x);
        ++total;
      }
      if (inside != 0 && inside != total)
        throw InputError(spec.file, f.line, "forces." + f.name,
                         "the stress surface cuts coil " + coils[k].name);
      coil_in[k] = inside == total;
    }
    std::vector<AnalyticMagnet> in, out;
    for (const auto& m : magnets)
      (magnet_inside(f, m) ? in : out).push_back(m);
    ForceTorque total;
    if (!in.empty() && !out.empty()) {
      PairInteractionOptions o;
      o.tolerance = field_options.tolerance;
      o.n_threads = field_options.n_threads;
      total = total + pair_interaction(in, out, f.torque_point, o).on_A;
    }
    for (std::size_t k = 0; k < coils.size(); ++k) {
      if (coil_in[k]) {
        total = total +
                coil_wrench(*fields[k],
                            field_of(out, other_coils([&](std::size_t j) { return !coil_in[j]; }),
                                     field_options),
                            f.torque_point);
      } else if (!in.empty()) {
        // Action = reaction: the enclosed magnets feel minus the coil's force in their field.
        total = total - coil_wrench(*fields[k], field_of(in, {}, field_options), f.torque_point);
      }
    }
    r.force = total.force;
    r.torque = total.torque;
    run.forces.push_back(r);
  }
}

} // namespace magfem
