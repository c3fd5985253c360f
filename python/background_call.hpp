#pragma once
// A long library call (a sweep's positions on their worker threads) run from Python so that
// Ctrl-C and a progress callable work while it runs.
//
// Why a thread of its own: Python runs its SIGINT handler (which raises KeyboardInterrupt)
// only on the main thread, and the position runner makes its calling thread one of the
// workers, busy inside a solve. So the work runs on a thread of its own and the calling thread
// waits without the GIL, waking every 50 ms to run the signal handlers and to pass on, with
// the GIL held and on the caller's thread, the progress reports the workers queued. A
// KeyboardInterrupt (or an exception of the callable) asks the work to stop through its
// stop token, is kept until the work has returned (positions under way finish: a position
// is not interrupted inside its solve), and is then raised.
#include <functional>
#include <mutex>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

namespace magfem::python {

class BackgroundCall {
public:
  // progress: None (silent), True (a "position i/n done" line on stderr per report, `item`
  // naming what is done) or a callable progress(done, total). Constructed with the GIL held.
  explicit BackgroundCall(pybind11::object progress, std::string item = "position");

  // From any thread: queues a report for the caller's thread.
  void report(int done, int total);
  std::stop_token stop_token() const { return stop_.get_token(); }

  // Runs work() on a thread of its own, the calling thread (GIL held) waiting as above;
  // rethrows work's exception, or the KeyboardInterrupt / callable's exception that stopped
  // it.
  void run(const std::function<void()>& work);

private:
  void pass_reports(); // GIL held

  pybind11::object callback_;
  bool print_ = false;
  std::string item_;
  std::stop_source stop_;
  std::mutex mutex_;
  std::vector<std::pair<int, int>> queued_;
};

} // namespace magfem::python
