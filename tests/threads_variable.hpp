#pragma once
// MAGFEM_THREADS (core/thread_count.hpp's available_threads()) set for a scope, for tests that
// compare one thread count against another; the previous value (or none) comes back after.
#include <cstdlib>
#include <string>

namespace magfem::test {

class ThreadsVariable {
public:
  explicit ThreadsVariable(const char* n) {
    if (const char* old = std::getenv("MAGFEM_THREADS"))
      previous_ = old, had_ = true;
    setenv("MAGFEM_THREADS", n, 1);
  }
  ~ThreadsVariable() {
    if (had_)
      setenv("MAGFEM_THREADS", previous_.c_str(), 1);
    else
      unsetenv("MAGFEM_THREADS");
  }
  ThreadsVariable(const ThreadsVariable&) = delete;
  ThreadsVariable& operator=(const ThreadsVariable&) = delete;

private:
  std::string previous_;
  bool had_ = false;
};

} // namespace magfem::test
