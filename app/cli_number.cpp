#include "app/cli_number.hpp"

#include <cmath>
#include <stdexcept>

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

} // namespace magfem
