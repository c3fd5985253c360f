#include "python/background_call.hpp"

#include <chrono>
#include <cstdio>
#include <exception>
#include <future>
#include <thread>

namespace py = pybind11;

namespace magfem::python {
namespace {
// Often enough that Ctrl-C and progress feel immediate, rarely enough to cost nothing.
constexpr std::chrono::milliseconds poll_interval{50};
} // namespace

BackgroundCall::BackgroundCall(py::object progress, std::string item) : item_(std::move(item)) {
  if (py::isinstance<py::bool_>(progress))
    print_ = progress.cast<bool>();
  else if (!progress.is_none())
    callback_ = std::move(progress);
}

void BackgroundCall::report(int done, int total) {
  const std::lock_guard lock(mutex_);
  queued_.emplace_back(done, total);
}

void BackgroundCall::pass_reports() {
  std::vector<std::pair<int, int>> reports;
  {
    const std::lock_guard lock(mutex_);
    reports.swap(queued_);
  }
  for (const auto& [done, total] : reports) {
    if (print_)
      std::fprintf(stderr, "%s %d/%d done\n", item_.c_str(), done, total);
    if (callback_)
      callback_(done, total);
  }
}

void BackgroundCall::run(const std::function<void()>& work) {
  std::packaged_task<void()> task(work);
  std::future<void> finished = task.get_future();
  std::exception_ptr raised;
  {
    std::jthread worker(std::move(task));
    for (bool done = false; !done;) {
      {
        const py::gil_scoped_release release;
        done = finished.wait_for(poll_interval) == std::future_status::ready;
      }
      if (raised)
        continue; // stopping: wait for the positions under way
      try {
        pass_reports();
        if (PyErr_CheckSignals() != 0)
          throw py::error_already_set();
      } catch (...) {
        raised = std::current_exception();
        stop_.request_stop();
      }
    }
  }
  if (raised)
    std::rethrow_exception(raised);
  finished.get(); // work's own exception (InputError, ...)
}

} // namespace magfem::python
