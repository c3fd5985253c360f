#include "python/option_arguments.hpp"

#include <cstdio>

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

} // namespace magfem::python
