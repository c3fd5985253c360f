// SourceFieldCache3D: computes each point once, finds a point recomputed in another
// floating-point order, keeps values per point apart, respects its size limit, and is safe
// under concurrent use.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "solver/source_field_cache3d.hpp"

using namespace magfem;

namespace {

// Two values per point that identify the point.
void field(const Eigen::Vector3d& x, Eigen::Vector3d* out) {
  out[0] = 2 * x;
  out[1] = Eigen::Vector3d(x.y(), x.z(), x.x());
}

} // namespace

TEST(SourceFieldCache3D, ComputesEachPointOnceAndFindsItAgain) {
  SourceFieldCache3D cache(2, 1000);
  int calls = 0;
  const auto compute = [&](const Eigen::Vector3d& x, Eigen::Vector3d* out) {
    ++calls;
    field(x, out);
  };
  Eigen::Vector3d out[2];
  const Eigen::Vector3d a(0.1, 0.2, 0.3), b(0.3, 0.2, 0.1);
  for (int i = 0; i < 3; ++i) {
    cache.get(a, compute, out);
    EXPECT_EQ(out[0], 2 * a);
    EXPECT_EQ(out[1], Eigen::Vector3d(0.2, 0.3, 0.1));
    cache.get(b, compute, out);
    EXPECT_EQ(out[0], 2 * b);
  }
  EXPECT_EQ(calls, 2);
  // The same point as another stage computes it (barycentric sums in another order): found.
  const Eigen::Vector3d p(0.013, -0.027, 0.041), q(-0.008, 0.019, 0.005);
  cache.get(0.3 * p + 0.7 * q, compute, out);
  cache.get(0.7 * q + 0.3 * p, compute, out);
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(cache.size(), 3u);
}

TEST(SourceFieldCache3D, StopsStoringAtItsLimitButStillAnswers) {
  SourceFieldCache3D cache(2, 10);
  Eigen::Vector3d out[2];
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3d x(i, 0.5 * i, -0.25 * i);
    cache.get(x, field, out);
    EXPECT_EQ(out[0], 2 * x);
  }
  // The limit is split over the shards, each rounding up: at most limit + one per shard.
  EXPECT_LE(cache.size(), 10u + 64u);
}

TEST(SourceFieldCache3D, ConcurrentLookupsAgree) {
  SourceFieldCache3D cache(2, 100000);
  std::atomic<int> wrong{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < 4; ++t)
    pool.emplace_back([&] {
      Eigen::Vector3d out[2];
      for (int i = 0; i < 20000; ++i) {
        const Eigen::Vector3d x(i % 997, 0.001 * i, 1.0);
        cache.get(x, field, out);
        if (out[0] != 2 * x || out[1] != Eigen::Vector3d(x.y(), x.z(), x.x()))
          ++wrong;
      }
    });
  for (auto& th : pool)
    th.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(cache.size(), 20000u);
}
