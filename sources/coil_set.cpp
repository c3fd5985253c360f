#include "sources/coil_set.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace magfem {

CoilSet::CoilSet(const std::vector<Coil3D>& coils, const CoilFieldOptions& options) {
  fields_.reserve(coils.size());
  for (const Coil3D& c : coils) {
    fields_.emplace_back(c, options);
  }
}

Vec3 CoilSet::H(const Vec3& x) const {
  Vec3 h = Vec3::Zero();
  for (const CoilField& f : fields_) {
    h += f.H(x);
  }
  return h;
}

void CoilSet::H_at(const std::vector<Vec3>& points, std::vector<Vec3>& out, int threads) const {
  out.assign(points.size(), Vec3::Zero());
  std::size_t n_threads = threads > 0 ? static_cast<std::size_t>(threads)
                                      : std::max(1u, std::thread::hardware_concurrency());
  // Blocks of a few hundred points keep the threads busy to the end (the cost per point varies
  // by orders of magnitude between far and near points) at negligible scheduling cost.
  constexpr std::size_t block = 256;
  const std::size_t n_blocks = (points.size() + block - 1) / block;
  n_threads = std::min(n_threads, std::max<std::size_t>(n_blocks, 1));
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    try {
      for (std::size_t b = next++; b < n_blocks; b = next++) {
        const std::size_t end = std::min(points.size(), (b + 1) * block);
        for (std::size_t i = b * block; i < end; ++i) {
          out[i] = H(points[i]);
        }
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) {
        error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < n_threads; ++t) {
    pool.emplace_back(work);
  }
  work();
  for (std::thread& t : pool) {
    t.join();
  }
  if (error) {
    std::rethrow_exception(error);
  }
}

} // namespace magfem
