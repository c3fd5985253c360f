#pragma once
// The one loop over independent items (run_items): a sweep's positions (3D and planar
// rotate and move, axisymmetric move; run_positions is the sweeps' form), a study's designs,
// validate's catalogue entries and actuator --verify's solves. Items are taken from the
// checkpoint when an earlier run finished them (--resume), else computed on a pool of
// `workers` threads (the calling thread is one of them) and recorded as each finishes; failed
// items are not recorded, so that --resume tries them again. Rows come back in the order of
// the items whatever the order they finished in. solve(row, item) fills a fresh row; the
// runner times it, and an exception becomes the row's error (ok false): a failed item never
// stops the others (EndsRun below is the exception that does).
// A stop asked through `cancel` (Ctrl-C in Python, python/background_call.hpp) starts no
// further item: the items under way finish, the others come back as default rows (ok false,
// no error), which the caller throws away.
//
// Under mpirun (`world` distributed) the items are dealt to the processes instead, one at a
// time as each asks (solver/mpi_context.hpp WorkDealer); each process solves its items on its
// own `workers` threads, each item a serial computation of that process, and sends each row
// (its JSON codec, doubles exact) to rank 0 as it finishes. Rank 0 alone reads and writes the
// checkpoint (it deals only the items missing from it), records the rows as they arrive, and
// alone gets the rows back (in the order of the items, as a serial run would); the others get
// none.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <stop_token>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/thread_count.hpp"
#include "pipeline/run_checkpoint.hpp"
#include "solver/mpi_context.hpp"

namespace magfem {

// A row to and from its checkpoint record. An item is what the runner deals (a sweep's
// position, a study's design, a validation entry); `key` names it in the checkpoint (empty: a
// position's exact value, RunCheckpoint::key_of). from_json gives nothing for a record of
// another shape, which is then computed again.
template <class Row, class Item = double> struct PositionCodec {
  std::function<nlohmann::json(const Row&)> to_json; // a finished row, for the checkpoint
  std::function<std::optional<Row>(const nlohmann::json&, const Item&)> from_json;
  std::function<std::string(const Item&)> key;

  std::string key_of(const Item& item) const {
    if (key)
      return key(item);
    if constexpr (std::is_arithmetic_v<Item>)
      return RunCheckpoint::key_of(item);
    else
      throw std::logic_error("PositionCodec: a non-numeric item needs a key");
  }
};

// After each row (restored from the checkpoint or computed, here or on another process):
// the row, how many are done of how many, and whether the checkpoint had it. Serialized.
template <class Row>
using RowProgress = std::function<void(const Row& row, int done, int total, bool restored)>;

// Thrown by a solve to end the whole run instead of failing its item (an option that is bad
// for every item, which should be reported once, as bad input): run_items throws `error`.
struct EndsRun {
  std::exception_ptr error;
};

// Position workers of one process by default (--jobs not given): one per core, or under
// mpirun the process's share of its machine's cores (threads_per_process); at most one per
// position.
inline int default_position_workers(const MpiWorld& world, int requested, int n_positions) {
  const int cores = threads_per_process(world);
  return std::clamp(requested > 0 ? requested : cores, 1, std::max(n_positions, 1));
}

namespace position_detail {

// One item: solved, timed, and its exception (if any) become the row's error. A solve may
// also mark its row failed itself (ok false: a validation entry out of its tolerance is a
// result to report, but is not kept in the checkpoint, so that --resume evaluates it again).
template <class Row, class Item>
void solve_timed(Row& row, const Item& item, const std::function<void(Row&, const Item&)>& solve) {
  const auto t0 = std::chrono::steady_clock::now();
  try {
    row.ok = true;
    solve(row, item);
  } catch (const std::exception& e) {
    row.ok = false;
    row.error = e.what();
  }
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A row as it travels to rank 0: the checkpoint's fields (doubles exact) plus what the
// checkpoint leaves out, the outcome (a failed row is reported in summary.json too).
template <class Row, class Item>
std::string row_to_wire(const Row& row, const PositionCodec<Row, Item>& codec) {
  return nlohmann::json{
      {"ok", row.ok}, {"error", row.error}, {"seconds", row.seconds}, {"row", codec.to_json(row)}}
      .dump();
}

template <class Row, class Item>
Row row_from_wire(const std::string& text, const Item& item,
                  const PositionCodec<Row, Item>& codec) {
  const auto j = nlohmann::json::parse(text);
  const std::optional<Row> read = codec.from_json(j.at("row"), item);
  if (!read) // the same build wrote it: a bug, not a user's input
    throw std::logic_error("a row sent by another process does not read back");
  Row row = *read;
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

// The checkpoint's record of `item`, if it has one of this build's shape.
template <class Row, class Item>
std::optional<Row> restored_row(RunCheckpoint* checkpoint, const Item& item,
                                const PositionCodec<Row, Item>& codec) {
  const auto saved = checkpoint ? checkpoint->find(codec.key_of(item)) : std::nullopt;
  return saved ? codec.from_json(*saved, item) : std::nullopt;
}

// Rank 0: deals the items the checkpoint lacks, solves some on its own workers while its
// calling thread serves the other processes, and keeps every row as it arrives.
template <class Row, class Item>
std::vector<Row> deal_items(const std::vector<Item>& items, int workers, RunCheckpoint* checkpoint,
                            const PositionCodec<Row, Item>& codec,
                            const std::function<void(Row&, const Item&)>& solve,
                            const RowProgress<Row>& progress) {
  const int total = static_cast<int>(items.size());
  std::vector<Row> rows(items.size());
  std::vector<int> todo;
  int done = 0;
  std::mutex mutex;
  const auto keep = [&](int i, Row&& row, bool restored) {
    if (checkpoint && row.ok && !restored)
      checkpoint->record(codec.key_of(items[i]), codec.to_json(row));
    const std::lock_guard<std::mutex> lock(mutex);
    rows[i] = std::move(row);
    if (progress)
      progress(rows[i], ++done, total, restored);
  };
  for (int i = 0; i < total; ++i) {
    if (auto saved = restored_row(checkpoint, items[i], codec))
      keep(i, std::move(*saved), true);
    else
      todo.push_back(i);
  }
  WorkDealer dealer(std::move(todo), workers);
  WorkerPool pool;
  pool.start(workers, [&](int w, std::stop_token stop) {
    for (int i; !stop.stop_requested() && (i = dealer.next(w)) >= 0;) {
      Row row;
      solve_timed(row, items[i], solve);
      keep(i, std::move(row), false);
    }
  });
  dealer.serve([&](int i, const std::string& text) {
    keep(i, row_from_wire<Row>(text, items[i], codec), false);
  });
  pool.join();
  return rows;
}

// The other processes: ask rank 0 for items until none is left, sending each row back with
// the next request.
template <class Row, class Item>
void solve_dealt_items(const std::vector<Item>& items, int workers,
                       const PositionCodec<Row, Item>& codec,
                       const std::function<void(Row&, const Item&)>& solve) {
  WorkDealer dealer({}, workers);
  const auto work = [&](int w, std::stop_token stop) {
    int finished = -1;
    std::string result;
    for (int i; !stop.stop_requested() && (i = dealer.next(w, finished, result)) >= 0;) {
      Row row;
      solve_timed(row, items[i], solve);
      finished = i;
      result = row_to_wire(row, codec);
    }
  };
  WorkerPool pool;
  pool.start(workers - 1, [&](int w, std::stop_token stop) { work(w + 1, stop); });
  pool.run_here(0, work);
  pool.join();
}

// Serially on `workers` threads, or dealt across the processes of `world`.
template <class Row, class Item>
std::vector<Row> run_items_here(const std::vector<Item>& items, int workers,
                                RunCheckpoint* checkpoint, const PositionCodec<Row, Item>& codec,
                                const std::function<void(Row&, const Item&)>& solve,
                                const RowProgress<Row>& progress, const MpiWorld& world,
                                std::stop_token cancel) {
  if (world.distributed()) {
    // Without MPI_THREAD_MULTIPLE only one thread of a process may call MPI: rank 0 then
    // only deals, and every other process solves one item at a time.
    if (world.is_root())
      return deal_items(items, world.any_thread_calls_mpi ? workers : 0, checkpoint, codec, solve,
                        progress);
    solve_dealt_items(items, world.any_thread_calls_mpi ? workers : 1, codec, solve);
    return {};
  }
  const int total = static_cast<int>(items.size());
  std::vector<Row> rows(items.size());
  std::atomic<int> next{0};
  int done = 0;
  std::mutex mutex;
  const auto work = [&](int, std::stop_token stop) {
    for (int i; !stop.stop_requested() && !cancel.stop_requested() && (i = next++) < total;) {
      auto saved = restored_row(checkpoint, items[i], codec);
      if (saved) {
        rows[i] = std::move(*saved);
      } else {
        rows[i] = Row{};
        solve_timed(rows[i], items[i], solve);
        if (checkpoint && rows[i].ok)
          checkpoint->record(codec.key_of(items[i]), codec.to_json(rows[i]));
      }
      const std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (progress)
        progress(rows[i], done, total, saved.has_value());
    }
  };
  WorkerPool pool;
  pool.start(workers - 1, work);
  pool.run_here(0, work);
  pool.join();
  return rows;
}

} // namespace position_detail

// The independent items of a run (a sweep's positions, a study's designs, validation
// entries), serially on `workers` threads or dealt across the processes of `world`, as the
// header says; rows in the order of `items` (none on the processes other than rank 0).
template <class Row, class Item>
std::vector<Row> run_items(const std::vector<Item>& items, int workers, RunCheckpoint* checkpoint,
                           const PositionCodec<Row, Item>& codec,
                           const std::function<void(Row&, const Item&)>& solve,
                           const RowProgress<Row>& progress, const MpiWorld& world = {},
                           std::stop_token cancel = {}) {
  using namespace position_detail;
  // Items are a run's parallelism (threads, processes); an item's own BLAS stays on one
  // thread, so that its result does not depend on how many there are: the outputs are the
  // same bits with any --jobs and under mpirun with any number of processes (whose binding
  // to cores would otherwise give each a different OpenBLAS thread count).
  const BlasThreads one_blas_thread(1);
  try {
    return run_items_here(items, workers, checkpoint, codec, solve, progress, world, cancel);
  } catch (const EndsRun& end) {
    std::rethrow_exception(end.error);
  }
}

// A sweep's positions (a number each: degrees or metres), with a progress that counts.
template <class Row>
std::vector<Row> run_positions(const std::vector<double>& positions, int workers,
                               RunCheckpoint* checkpoint, const PositionCodec<Row>& codec,
                               const std::function<void(Row&, double)>& solve,
                               const std::function<void(int done, int total)>& progress,
                               const MpiWorld& world = {}, std::stop_token cancel = {}) {
  RowProgress<Row> counted;
  if (progress)
    counted = [&](const Row&, int done, int total, bool) { progress(done, total); };
  return run_items<Row, double>(
      positions, workers, checkpoint, codec,
      [&](Row& row, const double& position) { solve(row, position); }, counted, world, cancel);
}

} // namespace magfem
