#include "sources/coil_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"
#include "core/gauss_legendre.hpp"

namespace magfem {

namespace {

void check_racetrack(const Racetrack& r) {
  if (!(r.straight_x >= 0 && r.straight_y >= 0 && r.inner_radius >= 0 && r.width > 0 &&
        r.height > 0)) {
    throw std::invalid_argument("Racetrack: need straight_x, straight_y, inner_radius >= 0 and "
                                "width, height > 0");
  }
}

// The racetrack's four corners in counter-clockwise order, starting at (+x, -y): centre and the
// angle where the quarter begins (it ends a quarter turn later).
struct Corner {
  double cx, cy, phi0;
};
std::array<Corner, 4> racetrack_corners(const Racetrack& r) {
  const double hx = 0.5 * r.straight_x, hy = 0.5 * r.straight_y;
  return {{{hx, -hy, -0.5 * pi}, {hx, hy, 0.0}, {-hx, hy, 0.5 * pi}, {-hx, -hy, pi}}};
}

// A straight side in the StraightBundle convention: the corner of its box where the current
// enters, on the outer face and the bottom (z = -height/2); the current direction t; e_p
// pointing inwards, so that e_q = t x e_p = +z for a counter-clockwise current; its length.
struct Side {
  Vec3 origin, t, e_p;
  double length;
};
std::array<Side, 4> racetrack_sides(const Racetrack& r) {
  const double hx = 0.5 * r.straight_x, hy = 0.5 * r.straight_y;
  const double out = r.inner_radius + r.width, z = -0.5 * r.height;
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY();
  return {{{Vec3(-hx, -hy - out, z), x, y, r.straight_x},
           {Vec3(hx + out, -hy, z), y, -x, r.straight_y},
           {Vec3(hx, hy + out, z), -x, -y, r.straight_x},
           {Vec3(-hx - out, hy, z), -y, x, r.straight_y}}};
}

} // namespace

CoilField::CoilField(const Coil3D& coil, const CoilFieldOptions& options) : coil_(coil) {
  // The pieces carry the coil's ampere-turns for 1 A per turn.
  const double ni = coil.turns;
  if (const auto* c = std::get_if<SphericalCoil>(&coil.shape)) {
    axisymmetric_.emplace(*c, ni, options);
  } else if (const auto* s = std::get_if<Solenoid>(&coil.shape)) {
    axisymmetric_.emplace(*s, ni, options);
  } else {
    const auto& r = std::get<Racetrack>(coil.shape);
    check_racetrack(r);
    for (const Side& side : racetrack_sides(r)) {
      if (side.length > 0) {
        straights_.emplace_back(side.origin, side.t, side.e_p, side.length, r.width, r.height, ni,
                                options);
      }
    }
    for (const Corner& c : racetrack_corners(r)) {
      arcs_.emplace_back(Vec3(c.cx, c.cy, 0.0), c.phi0, c.phi0 + 0.5 * pi, r.inner_radius,
                         r.inner_radius + r.width, -0.5 * r.height, 0.5 * r.height, ni, options);
    }
  }
}

Vec3 CoilField::H_local_per_ampere(const Vec3& xl) const {
  if (axisymmetric_) {
    const double rho = std::sqrt(xl.x() * xl.x() + xl.y() * xl.y()); // hot path: not hypot
    const MeridianField m = axisymmetric_->H(rho, xl.z());
    Vec3 h(0.0, 0.0, m.h_z);
    if (rho > 0) {
      h.x() = m.h_rho * xl.x() / rho;
      h.y() = m.h_rho * xl.y() / rho;
    }
    return h;
  }
  Vec3 h = Vec3::Zero();
  for (const StraightBundle& s : straights_) {
    h += s.H(xl);
  }
  for (const ArcBundle& a : arcs_) {
    h += a.H(xl);
  }
  return h;
}

Vec3 CoilField::H_per_ampere(const Vec3& x) const {
  return coil_.placement.rotation * H_local_per_ampere(coil_.placement.to_local(x));
}

bool CoilField::contains_local(const Vec3& p) const {
  if (const auto* c = std::get_if<SphericalCoil>(&coil_.shape)) {
    const double r = p.norm();
    if (!(r > 0) || r < c->r_inner || r > c->r_outer) {
      return false;
    }
    const double alpha = std::atan2(std::hypot(p.x(), p.y()), p.z());
    return alpha >= c->alpha_min && alpha <= c->alpha_max;
  }
  if (const auto* s = std::get_if<Solenoid>(&coil_.shape)) {
    const double rho = std::hypot(p.x(), p.y());
    return rho >= s->r_inner && rho <= s->r_outer && std::abs(p.z()) <= 0.5 * s->length;
  }
  // Racetrack: the band between offsets inner_radius and inner_radius + width of the core
  // rectangle |x| <= straight_x / 2, |y| <= straight_y / 2 (distance to it).
  const auto& r = std::get<Racetrack>(coil_.shape);
  if (std::abs(p.z()) > 0.5 * r.height) {
    return false;
  }
  const double dx = std::max(std::abs(p.x()) - 0.5 * r.straight_x, 0.0);
  const double dy = std::max(std::abs(p.y()) - 0.5 * r.straight_y, 0.0);
  const double d = std::hypot(dx, dy);
  return d > 0 && d >= r.inner_radius && d <= r.inner_radius + r.width;
}

Vec3 CoilField::direction_local(const Vec3& p) const {
  Vec3 n(p.x(), p.y(), 0.0); // outward normal of the turn through p
  if (const auto* r = std::get_if<Racetrack>(&coil_.shape)) {
    n.x() -= std::clamp(p.x(), -0.5 * r->straight_x, 0.5 * r->straight_x);
    n.y() -= std::clamp(p.y(), -0.5 * r->straight_y, 0.5 * r->straight_y);
  }
  const double len = n.norm();
  if (!(len > 0)) {
    return Vec3::Zero();
  }
  return Vec3(-n.y(), n.x(), 0.0) / len; // counter-clockwise about +z
}

bool CoilField::contains(const Vec3& x) const {
  return contains_local(coil_.placement.to_local(x));
}

Vec3 CoilField::current_density(const Vec3& x) const {
  const Vec3 p = coil_.placement.to_local(x);
  if (!contains_local(p)) {
    return Vec3::Zero();
  }
  return coil_.placement.rotation *
         (coil_.turns * coil_.current / cross_section_area() * direction_local(p));
}

double CoilField::cross_section_area() const {
  if (const auto* c = std::get_if<SphericalCoil>(&coil_.shape)) {
    return 0.5 * (c->r_outer * c->r_outer - c->r_inner * c->r_inner) *
           (c->alpha_max - c->alpha_min);
  }
  if (const auto* s = std::get_if<Solenoid>(&coil_.shape)) {
    return (s->r_outer - s->r_inner) * s->length;
  }
  const auto& r = std::get<Racetrack>(coil_.shape);
  return r.width * r.height;
}

double CoilField::volume() const {
  if (const auto* c = std::get_if<SphericalCoil>(&coil_.shape)) {
    return 2.0 * pi / 3.0 * (std::pow(c->r_outer, 3) - std::pow(c->r_inner, 3)) *
           (std::cos(c->alpha_min) - std::cos(c->alpha_max));
  }
  if (const auto* s = std::get_if<Solenoid>(&coil_.shape)) {
    return pi * (s->r_outer * s->r_outer - s->r_inner * s->r_inner) * s->length;
  }
  const auto& r = std::get<Racetrack>(coil_.shape);
  const double ro = r.inner_radius + r.width;
  return r.height * (2.0 * (r.straight_x + r.straight_y) * r.width +
                     pi * (ro * ro - r.inner_radius * r.inner_radius));
}

double CoilField::resistance() const {
  return coil_.resistivity * coil_.turns * coil_.turns * mean_turn_length() /
         (coil_.fill_factor * cross_section_area());
}

Vec3 CoilField::magnetic_moment_per_ampere() const {
  double mean_area = 0;
  if (const auto* c = std::get_if<SphericalCoil>(&coil_.shape)) {
    // int pi (r sin a)^2 r dr da / A
    const double radial = (std::pow(c->r_outer, 4) - std::pow(c->r_inner, 4)) / 4.0;
    const double angular = 0.5 * (c->alpha_max - c->alpha_min) -
                           0.25 * (std::sin(2.0 * c->alpha_max) - std::sin(2.0 * c->alpha_min));
    mean_area = pi * radial * angular / cross_section_area();
  } else if (const auto* s = std::get_if<Solenoid>(&coil_.shape)) {
    mean_area = pi * (std::pow(s->r_outer, 3) - std::pow(s->r_inner, 3)) /
                (3.0 * (s->r_outer - s->r_inner));
  } else {
    // Turn at offset t from the core rectangle: (sx + 2t)(sy + 2t) - (4 - pi) t^2, averaged
    // over t in [R, R + w].
    const auto& r = std::get<Racetrack>(coil_.shape);
    auto primitive = [&](double t) {
      return r.straight_x * r.straight_y * t + (r.straight_x + r.straight_y) * t * t +
             pi * t * t * t / 3.0;
    };
    mean_area = (primitive(r.inner_radius + r.width) - primitive(r.inner_radius)) / r.width;
  }
  return coil_.turns * mean_area * (coil_.placement.rotation * Vec3::UnitZ());
}

std::vector<CoilQuadraturePoint> CoilField::volume_quadrature(int order, int n_azimuth) const {
  if (order < 1) {
    throw std::invalid_argument("CoilField::volume_quadrature: order must be >= 1");
  }
  const double j = coil_.turns / cross_section_area();
  std::vector<CoilQuadraturePoint> out;
  auto add = [&](const Vec3& xl, double w) {
    out.push_back(
        {coil_.placement.to_global(xl), w, coil_.placement.rotation * (j * direction_local(xl))});
  };
  // Axisymmetric coils: Gauss in the meridian parameters (in cos(alpha) for the spherical coil,
  // so that r^2 dr dcos(alpha) is polynomial and the volume exact), equally spaced azimuths
  // (exact for trigonometric polynomials of degree < 2 order; their directions sum to zero).
  if (axisymmetric_) {
    const int n_phi = std::max(4, n_azimuth > 0 ? n_azimuth : 2 * order);
    const auto* c = std::get_if<SphericalCoil>(&coil_.shape);
    const auto* s = std::get_if<Solenoid>(&coil_.shape);
    const QuadratureRule gu = c ? gauss_legendre(order, c->r_inner, c->r_outer)
                                : gauss_legendre(order, s->r_inner, s->r_outer);
    const QuadratureRule gv =
        c ? gauss_legendre(order, std::cos(c->alpha_max), std::cos(c->alpha_min))
          : gauss_legendre(order, -0.5 * s->length, 0.5 * s->length);
    for (std::size_t a = 0; a < gu.x.size(); ++a) {
      for (std::size_t b = 0; b < gv.x.size(); ++b) {
        double rho, z, w;
        if (c) {
          const double r = gu.x[a], ct = gv.x[b];
          rho = r * std::sqrt(std::max(0.0, 1.0 - ct * ct));
          z = r * ct;
          w = gu.w[a] * gv.w[b] * r * r;
        } else {
          rho = gu.x[a];
          z = gv.x[b];
          w = gu.w[a] * gv.w[b] * rho;
        }
        for (int k = 0; k < n_phi; ++k) {
          const double phi = 2.0 * pi * (k + 0.5) / n_phi;
          add(Vec3(rho * std::cos(phi), rho * std::sin(phi), z), w * 2.0 * pi / n_phi);
        }
      }
    }
    return out;
  }
  // Racetrack: tensor Gauss over each straight box; Gauss in (rho, z, phi) over each corner,
  // the same offsets in every corner so that the four corners' current directions cancel.
  const auto& r = std::get<Racetrack>(coil_.shape);
  const QuadratureRule g = gauss_legendre(order, 0.0, 1.0);
  for (const Side& side : racetrack_sides(r)) {
    if (!(side.length > 0)) {
      continue;
    }
    const Vec3 e_q = side.t.cross(side.e_p);
    for (std::size_t a = 0; a < g.x.size(); ++a) {
      for (std::size_t b = 0; b < g.x.size(); ++b) {
        for (std::size_t k = 0; k < g.x.size(); ++k) {
          const Vec3 xl = side.origin + g.x[a] * side.length * side.t +
                          g.x[b] * r.width * side.e_p + g.x[k] * r.height * e_q;
          add(xl, g.w[a] * g.w[b] * g.w[k] * side.length * r.width * r.height);
        }
      }
    }
  }
  for (const Corner& corner : racetrack_corners(r)) {
    for (std::size_t a = 0; a < g.x.size(); ++a) {
      const double rho = r.inner_radius + g.x[a] * r.width;
      for (std::size_t b = 0; b < g.x.size(); ++b) {
        const double z = (g.x[b] - 0.5) * r.height;
        for (std::size_t k = 0; k < g.x.size(); ++k) {
          const double phi = corner.phi0 + 0.5 * pi * g.x[k];
          const Vec3 xl(corner.cx + rho * std::cos(phi), corner.cy + rho * std::sin(phi), z);
          add(xl, g.w[a] * g.w[b] * g.w[k] * r.width * r.height * 0.5 * pi * rho);
        }
      }
    }
  }
  return out;
}

} // namespace magfem
