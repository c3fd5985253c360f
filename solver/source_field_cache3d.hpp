#pragma once
// Memo of a coil source field at points: every coil's H per ampere at a point, computed once.
// Why: the 3D pipeline evaluates H_s at the same quadrature points in several passes (source
// load, energy, flux linkage, the inductance's per-coil loads), and for coils without a fast
// expansion (racetracks: ~30 us per point) these passes dominate the run time.
//
// Points are keyed by their coordinates with the last 12 mantissa bits dropped, so that the
// same point computed by two stages in a different floating-point order is found (and two
// points that close, ~1e-12 relative, share a value, far below any FE error). Thread-safe
// (sharded locks). Stops storing beyond `max_points` points (memory), computing afresh.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

namespace magfem {

class SourceFieldCache3D {
public:
  // n_values: vectors stored per point (one per coil).
  SourceFieldCache3D(int n_values, std::size_t max_points);
  ~SourceFieldCache3D();

  // The n_values vectors at x: from the memo, or computed by `compute(x, out)` (out has
  // n_values entries) and stored.
  using Compute = std::function<void(const Eigen::Vector3d&, Eigen::Vector3d*)>;
  void get(const Eigen::Vector3d& x, const Compute& compute, Eigen::Vector3d* out) const;

  std::size_t size() const;

private:
  struct Shard;
  int n_values_;
  std::size_t max_per_shard_;
  std::vector<std::unique_ptr<Shard>> shards_;
};

} // namespace magfem
