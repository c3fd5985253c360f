#pragma once
// How many threads magfem's own parallel loops (3D assembly, B recovery, coil linkage) may
// use: the environment variable MAGFEM_THREADS when it is a positive integer (a machine
// shared with other work, or the determinism test comparing 1 and 2 threads), else the
// number of hardware threads. BLAS threads are OpenBLAS's own (OPENBLAS_NUM_THREADS).
#include <sched.h>

#include <cstddef>

namespace magfem {

int available_threads();

// Threads for a loop over n elements: all available, but one per ~20k elements at most (below
// that a thread's start-up outweighs its share of the work).
int element_loop_threads(std::size_t n_elements);

// The cores this process may run on (its CPU affinity mask; available_threads() where the
// mask cannot be read). Under mpirun each process is bound to its share; rank 0 borrows the
// others' for post-processing (lend_node_cores_to_root), which summary.json reports by this.
int cores_in_affinity();

// OpenBLAS on `n` threads for the life of this object (then as before). Its thread count is
// the one that changes results: CHOLMOD's supernodal factorization adds in an order that
// depends on it (1 and 2 threads differ in the 9th digit of a 2D sweep's force), while
// magfem's own loops give the same bits on any count. A no-op when the BLAS in use is not
// OpenBLAS (found at run time, so magfem does not link OpenBLAS itself).
// The calling thread may run on `cores` for the life of this object, then on its own cores
// again. Threads it starts meanwhile (OpenBLAS's, when BlasThreads raises their number)
// inherit the mask and keep it.
class ThreadOnCores {
public:
  explicit ThreadOnCores(const cpu_set_t& cores);
  ~ThreadOnCores();
  ThreadOnCores(const ThreadOnCores&) = delete;
  ThreadOnCores& operator=(const ThreadOnCores&) = delete;

private:
  cpu_set_t previous_;
  bool changed_ = false;
};

class BlasThreads {
public:
  explicit BlasThreads(int n);
  ~BlasThreads();
  BlasThreads(const BlasThreads&) = delete;
  BlasThreads& operator=(const BlasThreads&) = delete;

private:
  int previous_ = 0; // 0: not OpenBLAS
};

} // namespace magfem
