#include "core/thread_count.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <thread>

namespace magfem {

int available_threads() {
  if (const char* text = std::getenv("MAGFEM_THREADS")) {
    try {
      std::size_t used = 0;
      const int n = std::stoi(text, &used);
      if (used == std::string(text).size() && n > 0)
        return n;
    } catch (const std::exception&) {
    }
  }
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

int element_loop_threads(std::size_t n_elements) {
  constexpr std::size_t elements_per_thread = 20000;
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(available_threads()),
                                                1 + n_elements / elements_per_thread));
}

} // namespace magfem
