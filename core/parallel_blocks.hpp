#pragma once
// An index range [0, n) cut into fixed blocks that threads take in turn (dynamic: the work per
// block may vary, e.g. the coils' near field against their far field). The blocks do not
// depend on the thread count, so a caller that keeps one partial result per block and adds
// them in block order gets the same bits whatever the count or schedule.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace magfem {

inline std::size_t block_count(std::size_t n, std::size_t block) {
  return (n + block - 1) / block;
}

// body(worker, b, begin, end) for every block b = [begin, end), on n_threads threads (the
// caller's among them, worker 0); worker in [0, n_threads) names the thread, for scratch
// space that a thread reuses across its blocks.
template <class Body>
void parallel_blocks_by_worker(std::size_t n, std::size_t block, int n_threads, const Body& body) {
  const std::size_t n_blocks = block_count(n, block);
  std::atomic<std::size_t> next{0};
  auto work = [&](int worker) {
    for (std::size_t b; (b = next++) < n_blocks;)
      body(worker, b, b * block, std::min(n, (b + 1) * block));
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < n_threads; ++k)
    pool.emplace_back(work, k);
  work(0);
  for (auto& th : pool)
    th.join();
}

// body(b, begin, end) for every block b = [begin, end), on n_threads threads (the caller's
// among them).
template <class Body>
void parallel_blocks(std::size_t n, std::size_t block, int n_threads, const Body& body) {
  parallel_blocks_by_worker(
      n, block, n_threads,
      [&](int, std::size_t b, std::size_t lo, std::size_t hi) { body(b, lo, hi); });
}

} // namespace magfem
