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

Material Material::at_temperature(double T_C) const {
  if (kind != MaterialKind::magnet || temperature_C != MagnetKnee::reference_C)
    throw std::logic_error("at_temperature needs a magnet at 20 C ('" + name + "')");
  if (T_C == temperature_C)
    return *this;
  if (!knee.alpha_pct_per_K)
    throw std::logic_error("magnet '" + name + "' has no temperature coefficient of B_r");
  Material m = *this;
  m.B_r = MagnetKnee::at_temperature(B_r, *knee.alpha_pct_per_K, T_C);
  m.temperature_C = T_C;
  return m;
}

std::optional<double> Material::coercivity_Apm() const {
  if (kind != MaterialKind::magnet || !knee.HcJ_Apm)
    return std::nullopt;
  if (temperature_C == MagnetKnee::reference_C)
    return knee.HcJ_Apm;
  if (!knee.beta_pct_per_K)
    return std::nullopt; // H_cJ off 20 C unknown: no guess
  return MagnetKnee::at_temperature(*knee.HcJ_Apm, *knee.beta_pct_per_K, temperature_C);
}

std::optional<double> Material::knee_T() const {
  const auto hcj = coercivity_Apm();
  if (!hcj)
    return std::nullopt;
  return knee_flux_density(B_r, mu_r, *hcj);
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
