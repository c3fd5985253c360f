#pragma once
// How many threads magfem's own parallel loops (3D assembly, B recovery, coil linkage) may
// use: the environment variable MAGFEM_THREADS when it is a positive integer (a machine
// shared with other work, or the determinism test comparing 1 and 2 threads), else the
// number of hardware threads. BLAS threads are OpenBLAS's own (OPENBLAS_NUM_THREADS).
#include <cstddef>

namespace magfem {

int available_threads();

// Threads for a loop over n elements: all available, but one per ~20k elements at most (below
// that a thread's start-up outweighs its share of the work).
int element_loop_threads(std::size_t n_elements);

} // namespace magfem
