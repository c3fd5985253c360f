#pragma once
// The one position loop of every sweep (3D rotate, axisymmetric move, planar rotate): the
// positions of a sweep are independent solves, taken from the checkpoint when an earlier run
// finished them (--resume), else computed on a pool of `workers` threads (the calling thread
// is one of them) and recorded as each finishes; failed positions are not recorded, so that
// --resume tries them again. Rows come back in the order of the positions whatever the order
// they finished in. solve(row, position) fills a fresh row; the runner times it, and an
// exception becomes the row's error (ok false): a failed position never stops the others.
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "pipeline/run_checkpoint.hpp"

namespace magfem {

template <class Row> struct PositionCodec {
  std::function<nlohmann::json(const Row&)> to_json; // a finished row, for the checkpoint
  std::function<Row(const nlohmann::json&, double position)> from_json; // a restored row (ok)
};

template <class Row>
std::vector<Row> run_positions(const std::vector<double>& positions, int workers,
                               RunCheckpoint* checkpoint, const PositionCodec<Row>& codec,
                               const std::function<void(Row&, double)>& solve,
                               const std::function<void(int done, int total)>& progress) {
  const int total = static_cast<int>(positions.size());
  std::vector<Row> rows(positions.size());
  std::atomic<int> next{0};
  int done = 0;
  std::mutex mutex;
  const auto work = [&] {
    for (int i; (i = next++) < total;) {
      const std::string key = RunCheckpoint::key_of(positions[i]);
      const auto saved = checkpoint ? checkpoint->find(key) : std::nullopt;
      if (saved) {
        rows[i] = codec.from_json(*saved, positions[i]);
      } else {
        const auto t0 = std::chrono::steady_clock::now();
        try {
          solve(rows[i], positions[i]);
          rows[i].ok = true;
        } catch (const std::exception& e) {
          rows[i].ok = false;
          rows[i].error = e.what();
        }
        rows[i].seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (checkpoint && rows[i].ok)
          checkpoint->record(key, codec.to_json(rows[i]));
      }
      const std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (progress)
        progress(done, total);
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w)
    pool.emplace_back(work);
  work();
  for (auto& t : pool)
    t.join();
  return rows;
}

} // namespace magfem
