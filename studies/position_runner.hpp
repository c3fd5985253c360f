#pragma once
// The one position loop of every sweep (3D and planar rotate and move, axisymmetric move): the
// positions of a sweep are independent solves, taken from the checkpoint when an earlier run
// finished them (--resume), else computed on a pool of `workers` threads (the calling thread
// is one of them) and recorded as each finishes; failed positions are not recorded, so that
// --resume tries them again. Rows come back in the order of the positions whatever the order
// they finished in. solve(row, position) fills a fresh row; the runner times it, and an
// exception becomes the row's error (ok false): a failed position never stops the others.
// A stop asked through `cancel` (Ctrl-C in Python, python/background_call.hpp) starts no
// further position: the positions under way finish, the others come back as default rows
// (ok false, no error), which the caller throws away.
//
// Under mpirun (`world` distributed) the positions are dealt to the processes instead, one at
// a time as each asks (solver/mpi_context.hpp WorkDealer); each process solves its positions
// on its own `workers` threads, each position a serial solve of that process, and sends each
// row to rank 0 as it finishes. Rank 0 alone reads and writes the checkpoint (it deals only
// the positions missing from it), records the rows as they arrive, and alone gets the rows
// back (in the order of the positions, as a serial run would); the others get none.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/thread_count.hpp"
#include "pipeline/run_checkpoint.hpp"
#include "solver/mpi_context.hpp"

namespace magfem {

template <class Row> struct PositionCodec {
  std::function<nlohmann::json(const Row&)> to_json; // a finished row, for the checkpoint
  std::function<Row(const nlohmann::json&, double position)> from_json; // a restored row (ok)
};

// Position workers of one process by default (--jobs not given): one per core, or under
// mpirun the process's share of its machine's cores (threads_per_process); at most one per
// position.
inline int default_position_workers(const MpiWorld& world, int requested, int n_positions) {
  const int cores = threads_per_process(world);
  return std::clamp(requested > 0 ? requested : cores, 1, std::max(n_positions, 1));
}

namespace position_detail {

// One position: solved, timed, and its exception (if any) become the row's error.
template <class Row>
void solve_timed(Row& row, double position, const std::function<void(Row&, double)>& solve) {
  const auto t0 = std::chrono::steady_clock::now();
  try {
    solve(row, position);
    row.ok = true;
  } catch (const std::exception& e) {
    row.ok = false;
    row.error = e.what();
  }
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A row as it travels to rank 0: the checkpoint's fields (doubles exact) plus what the
// checkpoint leaves out, the outcome (a failed row is reported in summary.json too).
template <class Row> std::string row_to_wire(const Row& row, const PositionCodec<Row>& codec) {
  return nlohmann::json{
      {"ok", row.ok}, {"error", row.error}, {"seconds", row.seconds}, {"row", codec.to_json(row)}}
      .dump();
}

template <class Row>
Row row_from_wire(const std::string& text, double position, const PositionCodec<Row>& codec) {
  const auto j = nlohmann::json::parse(text);
  Row row = codec.from_json(j.at("row"), position);
  row.ok = j.at("ok").get<bool>();
  row.error = j.at("error").get<std::string>();
  row.seconds = j.at("seconds").get<double>();
  return row;
}

// Worker threads, joined however the scope that owns them is left (an exception on the
// owner's thread asks them to stop after their current position). The first exception that
// escapes a worker (not a position's own: those become rows) is thrown again by join().
class WorkerPool {
public:
  void start(int n, const std::function<void(int worker, std::stop_token)>& work) {
    for (int w = 0; w < n; ++w)
      threads_.emplace_back([this, w, work](std::stop_token stop) { guarded(w, stop, work); });
  }
  void join() {
    for (auto& t : threads_)
      t.join();
    threads_.clear();
    if (error_)
      std::rethrow_exception(error_);
  }
  // Runs as one of the workers on the calling thread.
  void run_here(int w, const std::function<void(int, std::stop_token)>& work) {
    guarded(w, std::stop_token{}, work);
  }

private:
  void guarded(int w, std::stop_token stop, const std::function<void(int, std::stop_token)>& work) {
    try {
      work(w, stop);
    } catch (...) {
      const std::lock_guard lock(mutex_);
      if (!error_)
        error_ = std::current_exception();
    }
  }
  std::mutex mutex_;
  std::exception_ptr error_;
  std::vector<std::jthread> threads_; // last: stopped and joined first
};

// Rank 0: deals the positions the checkpoint lacks, solves some on its own workers while its
// calling thread serves the other processes, and keeps every row as it arrives.
template <class Row>
std::vector<Row> deal_positions(const std::vector<double>& positions, int workers,
                                RunCheckpoint* checkpoint, const PositionCodec<Row>& codec,
                                const std::function<void(Row&, double)>& solve,
                                const std::function<void(int done, int total)>& progress) {
  const int total = static_cast<int>(positions.size());
  std::vector<Row> rows(positions.size());
  std::vector<int> todo;
  int done = 0;
  std::mutex mutex;
  const auto keep = [&](int i, Row&& row) {
    if (checkpoint && row.ok)
      checkpoint->record(RunCheckpoint::key_of(positions[i]), codec.to_json(row));
    const std::lock_guard<std::mutex> lock(mutex);
    rows[i] = std::move(row);
    if (progress)
      progress(++done, total);
  };
  for (int i = 0; i < total; ++i) {
    const auto saved =
        checkpoint ? checkpoint->find(RunCheckpoint::key_of(positions[i])) : std::nullopt;
    if (saved)
      keep(i, codec.from_json(*saved, positions[i]));
    else
      todo.push_back(i);
  }
  WorkDealer dealer(std::move(todo), workers);
  WorkerPool pool;
  pool.start(workers, [&](int w, std::stop_token stop) {
    for (int i; !stop.stop_requested() && (i = dealer.next(w)) >= 0;) {
      Row row;
      solve_timed(row, positions[i], solve);
      keep(i, std::move(row));
    }
  });
  dealer.serve([&](int i, const std::string& text) {
    keep(i, row_from_wire<Row>(text, positions[i], codec));
  });
  pool.join();
  return rows;
}

// The other processes: ask rank 0 for positions until none is left, sending each row back
// with the next request.
template <class Row>
void solve_dealt_positions(const std::vector<double>& positions, int workers,
                           const PositionCodec<Row>& codec,
                           const std::function<void(Row&, double)>& solve) {
  WorkDealer dealer({}, workers);
  const auto work = [&](int w, std::stop_token stop) {
    int finished = -1;
    std::string result;
    for (int i; !stop.stop_requested() && (i = dealer.next(w, finished, result)) >= 0;) {
      Row row;
      solve_timed(row, positions[i], solve);
      finished = i;
      result = row_to_wire(row, codec);
    }
  };
  WorkerPool pool;
  pool.start(workers - 1, [&](int w, std::stop_token stop) { work(w + 1, stop); });
  pool.run_here(0, work);
  pool.join();
}

} // namespace position_detail

template <class Row>
std::vector<Row> run_positions(const std::vector<double>& positions, int workers,
                               RunCheckpoint* checkpoint, const PositionCodec<Row>& codec,
                               const std::function<void(Row&, double)>& solve,
                               const std::function<void(int done, int total)>& progress,
                               const MpiWorld& world = {}, std::stop_token cancel = {}) {
  using namespace position_detail;
  // Positions are a sweep's parallelism (threads, processes); a position's own BLAS stays on
  // one thread, so that its result does not depend on how many there are: a sweep's outputs
  // are the same bits with any --jobs and under mpirun with any number of processes (whose
  // binding to cores would otherwise give each a different OpenBLAS thread count).
  const BlasThreads one_blas_thread(1);
  if (world.distributed()) {
    // Without MPI_THREAD_MULTIPLE only one thread of a process may call MPI: rank 0 then
    // only deals, and every other process solves one position at a time.
    if (world.is_root())
      return deal_positions(positions, world.any_thread_calls_mpi ? workers : 0, checkpoint, codec,
                            solve, progress);
    solve_dealt_positions(positions, world.any_thread_calls_mpi ? workers : 1, codec, solve);
    return {};
  }
  const int total = static_cast<int>(positions.size());
  std::vector<Row> rows(positions.size());
  std::atomic<int> next{0};
  int done = 0;
  std::mutex mutex;
  const auto work = [&](int, std::stop_token stop) {
    for (int i; !stop.stop_requested() && !cancel.stop_requested() && (i = next++) < total;) {
      const std::string key = RunCheckpoint::key_of(positions[i]);
      const auto saved = checkpoint ? checkpoint->find(key) : std::nullopt;
      if (saved) {
        rows[i] = codec.from_json(*saved, positions[i]);
      } else {
        solve_timed(rows[i], positions[i], solve);
        if (checkpoint && rows[i].ok)
          checkpoint->record(key, codec.to_json(rows[i]));
      }
      const std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (progress)
        progress(done, total);
    }
  };
  WorkerPool pool;
  pool.start(workers - 1, work);
  pool.run_here(0, work);
  pool.join();
  return rows;
}

} // namespace magfem
