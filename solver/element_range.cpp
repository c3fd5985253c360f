#include "solver/element_range.hpp"

#include <algorithm>

namespace magfem {

ElementRange element_share(std::size_t n_elements, int rank, int size) {
  const auto r = static_cast<std::size_t>(rank), s = static_cast<std::size_t>(size);
  const std::size_t base = n_elements / s, extra = n_elements % s;
  const std::size_t first = r * base + std::min(r, extra);
  return {first, first + base + (r < extra ? 1 : 0)};
}

} // namespace magfem
