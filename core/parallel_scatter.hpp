#pragma once
// A deterministic parallel element loop: results identical to the serial loop bit for bit,
// whatever the number of threads.
//
// Threads that add element contributions straight into shared rows (atomic adds) sum each
// entry in whatever order they happen to arrive, so the last bits change from run to run and
// with the thread count. Here elements go in blocks: first every thread computes a share of
// the block's elements into a buffer, then every thread walks the whole block in element
// order and adds only the contributions to the targets (rows, DOFs) it owns. Each target is
// summed by one thread in the serial order.
#include <algorithm>
#include <barrier>
#include <cstddef>
#include <thread>
#include <vector>

namespace magfem {

// compute(e, double* out): writes element e's `per_element` values into out.
// scatter(e, const double* values, std::size_t lo, std::size_t hi): adds element e's values
// to the targets t with lo <= t < hi (and only those).
// `n_targets`: targets are numbered 0 .. n_targets - 1 and split evenly between threads.
template <class Compute, class Scatter>
void parallel_element_scatter(std::size_t n_elements, std::size_t per_element,
                              std::size_t n_targets, int n_threads, const Compute& compute,
                              const Scatter& scatter) {
  if (n_threads <= 1 || n_elements == 0) {
    std::vector<double> values(per_element);
    for (std::size_t e = 0; e < n_elements; ++e) {
      compute(e, values.data());
      scatter(e, values.data(), std::size_t{0}, n_targets);
    }
    return;
  }
  // 4096 elements a thread per block: P2 tetrahedra (110 values) need 3.6 MB a thread, and
  // the two barriers a block cost little against ~4000 element kernels.
  const std::size_t block = 4096 * static_cast<std::size_t>(n_threads);
  std::vector<double> buffer(std::min(block, n_elements) * per_element);
  std::barrier sync(n_threads);
  auto work = [&](int k) {
    const std::size_t lo = n_targets * k / n_threads, hi = n_targets * (k + 1) / n_threads;
    for (std::size_t b0 = 0; b0 < n_elements; b0 += block) {
      const std::size_t n = std::min(block, n_elements - b0);
      for (std::size_t i = n * k / n_threads; i < n * (k + 1) / n_threads; ++i)
        compute(b0 + i, &buffer[i * per_element]);
      sync.arrive_and_wait(); // the block is computed
      for (std::size_t i = 0; i < n; ++i)
        scatter(b0 + i, &buffer[i * per_element], lo, hi);
      sync.arrive_and_wait(); // the buffer is free for the next block
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < n_threads; ++k)
    pool.emplace_back(work, k);
  work(0);
  for (auto& t : pool)
    t.join();
}

} // namespace magfem
