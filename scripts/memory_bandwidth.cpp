// The machine's memory read bandwidth on 1 and 2 threads (GB/s), for scripts/target_timings.sh:
// benchmark32's CG and the sweep's solves stream their matrices and factors from memory, so
// this bounds them, and whether a second thread adds bandwidth says what two processes (issue
// 33's sweep) can gain. A 1.6 GB array summed, each count measured twice, the best kept.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <thread>
#include <vector>

namespace {

// Eight independent sums: one sum's chain of dependent additions would bound the loop at one
// addition per FP-add latency (~6 GB/s), below the memory's rate.
double sum(const double* begin, const double* end) {
  double s[8] = {};
  for (; begin + 8 <= end; begin += 8)
    for (int k = 0; k < 8; ++k)
      s[k] += begin[k];
  for (int k = 0; begin < end; ++begin, ++k)
    s[k] += *begin;
  return std::accumulate(s, s + 8, 0.0);
}

double read_bandwidth_gb_s(const std::vector<double>& a, int threads) {
  std::vector<double> partial(threads);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      const std::size_t lo = t * a.size() / threads, hi = (t + 1) * a.size() / threads;
      partial[t] = sum(a.data() + lo, a.data() + hi);
    });
  for (auto& th : pool)
    th.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (std::accumulate(partial.begin(), partial.end(), 0.0) != static_cast<double>(a.size()))
    std::fprintf(stderr, "memory_bandwidth: wrong sum\n"); // keeps the loads from being dropped
  return 8.0 * a.size() / seconds / 1e9;
}

} // namespace

int main() {
  const std::vector<double> a(200'000'000, 1.0);
  for (int threads : {1, 2}) {
    const double best = std::max(read_bandwidth_gb_s(a, threads), read_bandwidth_gb_s(a, threads));
    std::printf("%s%.1f", threads == 1 ? "" : " ", best);
  }
  std::printf("\n");
}
