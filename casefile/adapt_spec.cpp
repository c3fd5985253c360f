#include "casefile/adapt_spec.hpp"

#include <algorithm>
#include <array>

#include "casefile/case_spec.hpp"
#include "core/input_error.hpp"

namespace magfem {
namespace {

constexpr std::array<const char*, 8> force_components = {"Fx", "Fy", "Fz",    "Tx",
                                                         "Ty", "Tz", "force", "torque"};

template <class Named> bool has_name(const std::vector<Named>& v, const std::string& name) {
  return std::any_of(v.begin(), v.end(), [&](const Named& e) { return e.name == name; });
}

} // namespace

std::optional<AdaptQuantity> parse_adapt_quantity(const std::string& text, const CaseSpec& c,
                                                  std::string& why) {
  if (text == "energy")
    return AdaptQuantity{};
  if (text.rfind("forces.", 0) == 0) {
    // The component is after the last dot: force names may not hold dots, but be lenient.
    const std::size_t dot = text.rfind('.');
    const std::string name = text.substr(7, dot > 7 ? dot - 7 : 0);
    const std::string comp = dot > 7 ? text.substr(dot + 1) : "";
    if (!has_name(c.forces, name)) {
      why = "no force named '" + name + "' in the case (forces.NAME.COMPONENT)";
      return std::nullopt;
    }
    if (std::find(force_components.begin(), force_components.end(), comp) ==
        force_components.end()) {
      why = "unknown force component '" + comp + "' (Fx, Fy, Fz, Tx, Ty, Tz, force, torque)";
      return std::nullopt;
    }
    return AdaptQuantity{AdaptQuantity::Kind::force, name, comp};
  }
  if (text.rfind("probes.", 0) == 0) {
    const std::string name = text.substr(7);
    if (!has_name(c.probes, name)) {
      why = "no probe named '" + name + "' in the case";
      return std::nullopt;
    }
    return AdaptQuantity{AdaptQuantity::Kind::probe, name, ""};
  }
  why = "unknown quantity '" + text + "' (energy, forces.NAME.COMPONENT, probes.NAME)";
  return std::nullopt;
}

void apply_adapt_overrides(AdaptSpec& a, const AdaptOverrides& o, const AdaptOverrideNames& n) {
  if (o.accuracy_pct)
    a.accuracy_pct = *o.accuracy_pct;
  if ((o.max_passes || o.max_unknowns) && !a.enabled())
    throw InputError(n.file, 0, o.max_passes ? n.max_passes : n.max_unknowns,
                     "applies to adaptive solves: give " + n.accuracy + " or an adapt: section");
  if (o.max_passes)
    a.max_passes = *o.max_passes;
  if (o.max_unknowns)
    a.max_unknowns = *o.max_unknowns;
}

} // namespace magfem
