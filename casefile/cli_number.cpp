#include "casefile/cli_number.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/input_error.hpp"

namespace magfem {

double parse_cli_number(const std::string& option, const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && std::isfinite(v))
      return v;
  } catch (const std::exception&) {
    // stod's own message ("stod") says nothing useful: fall through to ours
  }
  throw InputError("<command line>", 0, option, "expected a finite number, got '" + text + "'");
}

double parse_cli_mesh_scale(const std::string& text) {
  const double scale = parse_cli_number("--mesh-scale", text);
  if (!(scale > 0))
    throw InputError("<command line>", 0, "--mesh-scale", "must be positive");
  return scale;
}

void parse_cli_adapt(const std::string& option, const std::string& text, AdaptOverrides& o) {
  const double v = parse_cli_number(option, text);
  const auto refuse = [&](const char* why) { throw InputError("<command line>", 0, option, why); };
  if (option == "--accuracy") {
    if (!(v > 0 && v < 100))
      refuse("must be between 0 and 100 (exclusive), in percent");
    o.accuracy_pct = v;
  } else if (option == "--max-passes") {
    if (!(v >= 1) || v != std::floor(v))
      refuse("must be a whole number >= 1");
    o.max_passes = static_cast<int>(v);
  } else if (option == "--max-unknowns") {
    if (!(v > 0))
      refuse("must be positive");
    o.max_unknowns = v;
  } else {
    throw std::logic_error("parse_cli_adapt: not an adaptive option: " + option);
  }
}

void refuse_adapt_options_unless(const AdaptOverrides& o, bool allowed, const std::string& why) {
  if (allowed)
    return;
  for (const auto& [given, name] : {std::pair{o.accuracy_pct.has_value(), "--accuracy"},
                                    std::pair{o.max_passes.has_value(), "--max-passes"},
                                    std::pair{o.max_unknowns.has_value(), "--max-unknowns"}})
    if (given)
      throw InputError("<command line>", 0, name, why);
}

int parse_cli_order(const std::string& text) {
  const double order = parse_cli_number("--order", text);
  if (order != 1 && order != 2)
    throw InputError("<command line>", 0, "--order", "must be 1 or 2");
  return static_cast<int>(order);
}

void parse_cli_parameter(const std::string& text, ParameterOverrides& parameters) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("<command line>", 0, "--param", "expected NAME=VALUE, got '" + text + "'");
  parameters[text.substr(0, eq)] = parse_cli_number("--param", text.substr(eq + 1));
}

} // namespace magfem
