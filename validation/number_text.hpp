#pragma once
// Numbers as the validation pages and method lines print them: one rule, so a figure in a
// method line and the same figure in the report's table read alike.
#include <string>

namespace magfem {

// `v` to `significant` digits, without an exponent in the range people read (1e-4 .. 1e7)
// and without trailing zeros (0.2500 -> 0.25); outside that range "%g".
std::string round_text(double v, int significant = 4);

} // namespace magfem
