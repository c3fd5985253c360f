#include "core/thread_count.hpp"

#include <algorithm>
#include <cstdlib>
#include <dlfcn.h>
#include <sched.h>
#include <string>
#include <thread>

namespace magfem {

int available_threads() {
  if (const char* text = std::getenv("MAGFEM_THREADS")) {
    try {
      std::size_t used = 0;
      const int n = std::stoi(text, &used);
      if (used == std::string(text).size() && n > 0)
        return n;
    } catch (const std::exception&) {
    }
  }
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

int element_loop_threads(std::size_t n_elements) {
  constexpr std::size_t elements_per_thread = 20000;
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(available_threads()),
                                                1 + n_elements / elements_per_thread));
}

int cores_in_affinity() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof mask, &mask) != 0)
    return available_threads();
  return std::max(1, CPU_COUNT(&mask));
}

ThreadOnCores::ThreadOnCores(const cpu_set_t& cores) {
  CPU_ZERO(&previous_);
  changed_ = sched_getaffinity(0, sizeof previous_, &previous_) == 0 &&
             sched_setaffinity(0, sizeof cores, &cores) == 0;
}

ThreadOnCores::~ThreadOnCores() {
  if (changed_)
    sched_setaffinity(0, sizeof previous_, &previous_);
}

namespace {

using GetThreads = int (*)();
using SetThreads = void (*)(int);

// One of OpenBLAS's own entry points, if the process has OpenBLAS loaded (through CHOLMOD's
// BLAS): in the global scope, or else in libopenblas.so.0 loaded by a module (the PETSc module
// is opened RTLD_LOCAL, so a program that links no BLAS itself sees its OpenBLAS only there).
// RTLD_NOLOAD: never loads it.
void* openblas_symbol(const char* name) {
  if (void* f = dlsym(RTLD_DEFAULT, name))
    return f;
  void* library = dlopen("libopenblas.so.0", RTLD_LAZY | RTLD_NOLOAD);
  if (!library)
    return nullptr;
  void* f = dlsym(library, name);
  dlclose(library); // drops only the reference RTLD_NOLOAD took
  return f;
}
GetThreads openblas_get() {
  return reinterpret_cast<GetThreads>(openblas_symbol("openblas_get_num_threads"));
}
SetThreads openblas_set() {
  return reinterpret_cast<SetThreads>(openblas_symbol("openblas_set_num_threads"));
}

} // namespace

BlasThreads::BlasThreads(int n) {
  const GetThreads get = openblas_get();
  const SetThreads set = openblas_set();
  if (!get || !set)
    return;
  previous_ = get();
  set(n);
}

BlasThreads::~BlasThreads() {
  if (previous_ > 0)
    openblas_set()(previous_);
}

} // namespace magfem
