#include "python/option_arguments.hpp"

#include <cstdio>

#include "casefile/cli_number.hpp"

namespace magfem::python {

std::string option_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

InputError as_argument_error(const InputError& e, const std::string& where,
                             const std::map<std::string, std::string>& names) {
  if (e.file() != "<command line>")
    return e;
  const auto it = names.find(e.field());
  return it == names.end() ? e : InputError(where, 0, it->second, e.reason());
}

AdaptOverrides adapt_arguments(const std::string& where, std::optional<double> accuracy_pct,
                               std::optional<int> max_passes, std::optional<double> max_unknowns) {
  AdaptOverrides o;
  try {
    if (accuracy_pct)
      parse_cli_adapt("--accuracy", option_number(*accuracy_pct), o);
    if (max_passes)
      parse_cli_adapt("--max-passes", std::to_string(*max_passes), o);
    if (max_unknowns)
      parse_cli_adapt("--max-unknowns", option_number(*max_unknowns), o);
  } catch (const InputError& e) {
    throw as_argument_error(e, where, adapt_argument_names());
  }
  return o;
}

const std::map<std::string, std::string>& adapt_argument_names() {
  static const std::map<std::string, std::string> names{{"--accuracy", "accuracy"},
                                                        {"--max-passes", "max_passes"},
                                                        {"--max-unknowns", "max_unknowns"}};
  return names;
}

} // namespace magfem::python
