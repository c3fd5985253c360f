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

} // namespace magfem
