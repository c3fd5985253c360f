#include "validation/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace magfem {

std::string round_text(double v, int significant) {
  char buf[64];
  const double a = std::abs(v);
  if (v == 0 || (a >= 1e-4 && a < 1e7)) {
    const int digits = v == 0 ? 0 : significant - 1 - static_cast<int>(std::floor(std::log10(a)));
    std::snprintf(buf, sizeof buf, "%.*f", std::max(0, digits), v);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
      s.erase(s.find_last_not_of('0') + 1);
      if (s.back() == '.')
        s.pop_back();
    }
    return s;
  }
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

} // namespace magfem
