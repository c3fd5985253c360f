#include "core/interrupt.hpp"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <semaphore.h>
#include <thread>

namespace magfem {
namespace {

// One per process by nature (signals are): the only global state in magfem.
struct Registry {
  std::mutex mutex;
  std::map<std::filesystem::path, std::filesystem::path> stages; // staging -> dir if empty
  bool installed = false;
};

Registry& registry() {
  static Registry r;
  return r;
}

[[noreturn]] void stop(int sig) {
  auto& r = registry();
  const std::lock_guard lock(r.mutex); // never released: no stage may commit after this
  std::size_t removed = 0;
  for (const auto& [staging, dir] : r.stages) {
    std::error_code ec;
    removed += std::filesystem::remove_all(staging, ec) > 0;
    if (!dir.empty() && std::filesystem::is_empty(dir, ec))
      std::filesystem::remove(dir, ec);
  }
  std::fprintf(stderr, "\nmagfem: interrupted by %s; %s\n", sig == SIGINT ? "SIGINT" : "SIGTERM",
               removed ? "unfinished outputs removed" : "no unfinished outputs");
  std::fflush(stderr);
  std::_Exit(128 + sig);
}

// The handler only records the signal and wakes the cleanup thread: sem_post is one of the
// few calls a handler may make. A handler rather than blocking the signals and sigwait():
// OpenBLAS starts its threads before main(), with the signals unblocked, and the kernel may
// deliver to any of them.
volatile std::sig_atomic_t received = 0;
sem_t wake;

void on_signal(int sig) {
  received = sig;
  sem_post(&wake);
}

} // namespace

void install_interrupt_handler() {
  auto& r = registry();
  const std::lock_guard lock(r.mutex);
  if (r.installed)
    return;
  r.installed = true;
  sem_init(&wake, 0, 0);
  std::thread([] {
    while (sem_wait(&wake) != 0) {
    }
    stop(received);
  }).detach();
  struct sigaction action {};
  action.sa_handler = on_signal;
  action.sa_flags = SA_RESTART; // system calls of the other threads carry on
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void register_staging(const std::filesystem::path& staging,
                      const std::filesystem::path& remove_dir_if_empty) {
  auto& r = registry();
  const std::lock_guard lock(r.mutex);
  r.stages[staging] = remove_dir_if_empty;
}

void unregister_staging(const std::filesystem::path& staging) {
  auto& r = registry();
  const std::lock_guard lock(r.mutex);
  r.stages.erase(staging);
}

std::unique_lock<std::mutex> hold_outputs() {
  return std::unique_lock(registry().mutex);
}

} // namespace magfem
