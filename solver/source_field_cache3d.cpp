#include "solver/source_field_cache3d.hpp"

#include <bit>
#include <mutex>
#include <unordered_map>

namespace magfem {
namespace {

constexpr int n_shards = 64;

using Key = std::array<std::uint64_t, 3>;

Key key_of(const Eigen::Vector3d& x) {
  constexpr std::uint64_t mask = ~std::uint64_t{0xfff};
  return {std::bit_cast<std::uint64_t>(x[0]) & mask, std::bit_cast<std::uint64_t>(x[1]) & mask,
          std::bit_cast<std::uint64_t>(x[2]) & mask};
}

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (std::uint64_t v : k)
      h = (h ^ v) * 0xff51afd7ed558ccdull, h ^= h >> 32;
    return static_cast<std::size_t>(h);
  }
};

} // namespace

struct SourceFieldCache3D::Shard {
  std::mutex mutex;
  std::unordered_map<Key, std::size_t, KeyHash> index; // key -> first value
  std::vector<Eigen::Vector3d> values;
};

SourceFieldCache3D::SourceFieldCache3D(int n_values, std::size_t max_points)
    : n_values_(n_values), max_per_shard_(max_points / n_shards + 1) {
  for (int s = 0; s < n_shards; ++s)
    shards_.push_back(std::make_unique<Shard>());
}

SourceFieldCache3D::~SourceFieldCache3D() = default;

void SourceFieldCache3D::get(const Eigen::Vector3d& x, const Compute& compute,
                             Eigen::Vector3d* out) const {
  const Key key = key_of(x);
  Shard& shard = *shards_[KeyHash{}(key) % n_shards];
  {
    std::lock_guard<std::mutex> lock(shard.mutex);
    const auto it = shard.index.find(key);
    if (it != shard.index.end()) {
      for (int k = 0; k < n_values_; ++k)
        out[k] = shard.values[it->second + k];
      return;
    }
  }
  // Computed outside the lock: two threads may compute the same point, which is harmless.
  compute(x, out);
  std::lock_guard<std::mutex> lock(shard.mutex);
  if (shard.index.size() >= max_per_shard_ || shard.index.count(key))
    return;
  shard.index.emplace(key, shard.values.size());
  shard.values.insert(shard.values.end(), out, out + n_values_);
}

std::size_t SourceFieldCache3D::size() const {
  std::size_t n = 0;
  for (const auto& s : shards_) {
    std::lock_guard<std::mutex> lock(s->mutex);
    n += s->index.size();
  }
  return n;
}

} // namespace magfem
