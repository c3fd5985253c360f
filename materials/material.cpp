#include "materials/material.hpp"

#include <stdexcept>

#include "core/constants.hpp"

namespace magfem {

void Material::reluctivity(double b2, double& nu, double& dnu_db2) const {
  if (kind == MaterialKind::soft) {
    if (!curve)
      throw std::logic_error("soft material '" + name + "' has no B-H curve");
    curve->nu_of_b2(b2, nu, dnu_db2);
    return;
  }
  // Linear and magnet: the reversible part is linear (the remanence is a source).
  nu = 1.0 / (mu0 * mu_r);
  dnu_db2 = 0.0;
}

void Material::permeability(double h2, double& mu, double& dmu_dh2) const {
  if (kind == MaterialKind::soft) {
    if (!curve)
      throw std::logic_error("soft material '" + name + "' has no B-H curve");
    curve->mu_of_h2(h2, mu, dmu_dh2);
    return;
  }
  mu = mu0 * mu_r;
  dmu_dh2 = 0.0;
}

double Material::start_permeability() const {
  if (kind != MaterialKind::soft)
    return mu0 * mu_r;
  return curve->peak_permeability();
}

Material Material::make_linear(std::string name, double mu_r, std::string source) {
  Material m;
  m.name = std::move(name);
  m.kind = MaterialKind::linear;
  m.mu_r = mu_r;
  m.source = std::move(source);
  return m;
}

Material Material::make_magnet(std::string name, double B_r, double mu_r, std::string source) {
  Material m = make_linear(std::move(name), mu_r, std::move(source));
  m.kind = MaterialKind::magnet;
  m.B_r = B_r;
  return m;
}

Material Material::make_soft(std::string name, std::shared_ptr<const BhCurve> curve,
                             std::string source) {
  if (!curve)
    throw std::logic_error("make_soft needs a B-H curve");
  Material m;
  m.name = std::move(name);
  m.kind = MaterialKind::soft;
  m.mu_r = curve->initial_slope() / mu0;
  m.curve = std::move(curve);
  m.source = std::move(source);
  return m;
}

const char* to_string(MaterialKind kind) {
  switch (kind) {
  case MaterialKind::linear:
    return "linear";
  case MaterialKind::magnet:
    return "magnet";
  case MaterialKind::soft:
    return "soft";
  }
  return "?";
}

} // namespace magfem
