// ThreadOnCores (core/thread_count.hpp): the distributed set-up widens the factor thread of
// process 0 onto the cores of the other processes for the factor only; the CG after it must
// run bound again, or two processes share a core. Checked: inside the scope the thread has
// exactly the given cores, after it its own again, and another thread is not touched (the
// call must be sched_setaffinity(0): a pid of the process would be the main thread's).
#include <gtest/gtest.h>

#include <sched.h>
#include <unistd.h>

#include <thread>

#include "core/thread_count.hpp"

namespace magfem {
namespace {

cpu_set_t own_cores() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  EXPECT_EQ(sched_getaffinity(0, sizeof mask, &mask), 0);
  return mask;
}

// One core the thread may run on now: the narrowing is then allowed wherever the test runs.
cpu_set_t one_of(const cpu_set_t& cores) {
  cpu_set_t one;
  CPU_ZERO(&one);
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &cores)) {
      CPU_SET(c, &one);
      break;
    }
  return one;
}

// On one core the narrowed mask is the whole mask, and neither test could see a scope that
// does nothing: skipped there, with the reason, rather than passing.
#define SKIP_ON_ONE_CORE(mask)                                                                     \
  if (CPU_COUNT(&(mask)) < 2)                                                                      \
  GTEST_SKIP() << "this process may run on one core only: narrowing to one core changes nothing"

TEST(ThreadOnCores, TheScopeHasTheGivenCoresThenTheThreadsOwn) {
  const cpu_set_t before = own_cores();
  SKIP_ON_ONE_CORE(before);
  const cpu_set_t one = one_of(before);
  ASSERT_EQ(CPU_COUNT(&one), 1);
  {
    const ThreadOnCores on(one);
    const cpu_set_t inside = own_cores();
    EXPECT_TRUE(CPU_EQUAL(&inside, &one));
    cpu_set_t other_thread;
    std::thread([&] { other_thread = own_cores(); }).join(); // inherits: started inside
    EXPECT_TRUE(CPU_EQUAL(&other_thread, &one));
  }
  const cpu_set_t after = own_cores();
  EXPECT_TRUE(CPU_EQUAL(&after, &before));
}

TEST(ThreadOnCores, LeavesTheOtherThreadsOfTheProcessAlone) {
  const cpu_set_t before = own_cores();
  SKIP_ON_ONE_CORE(before);
  cpu_set_t seen_by_main;
  std::thread([&] {
    const ThreadOnCores on(one_of(before));
    cpu_set_t main_now; // the main thread waits in join(): its mask is read from here
    CPU_ZERO(&main_now);
    ASSERT_EQ(sched_getaffinity(getpid(), sizeof main_now, &main_now), 0);
    seen_by_main = main_now;
  }).join();
  EXPECT_TRUE(CPU_EQUAL(&seen_by_main, &before));
}

} // namespace
} // namespace magfem
