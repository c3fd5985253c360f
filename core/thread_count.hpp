#pragma once
// How many threads magfem's own parallel loops (3D assembly, B recovery, coil linkage) may
// use: the environment variable MAGFEM_THREADS when it is a positive integer (a machine
// shared with other work, or the determinism test comparing 1 and 2 threads), else the
// number of hardware threads. BLAS threads are OpenBLAS's own (OPENBLAS_NUM_THREADS).
namespace magfem {

int available_threads();

} // namespace magfem
