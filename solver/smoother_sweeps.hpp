#pragma once
// Inside the PETSc module: pmg's fine-level smoother as PETSc's Richardson applies it
// (petsc_ksp_solver.cpp), serial and distributed in one. Serially BlockSmoother sweeps the
// whole system. Distributed, each process sweeps its own rows in place, and the whole is one
// Gauss-Seidel sweep over all processes' rows, as serially, in this order: going down, every
// process's rows that read no other process's unknowns (at once: they do not couple), then
// the rows that do, process 0's, then 1's, ... each process's after it has the previous
// processes' new values; going up the reverse, so up stays the transpose of down and CG's
// preconditioner symmetric. Block Jacobi across the processes (each sweeping from the others'
// old values) took 22 CG iterations on benchmark32 where the serial sweep takes 20. A
// process's right-hand side is b - A_off x (OffProcessRows): Richardson's step
// x + M^-1 (b - A x) without forming b - A x over the whole matrix first.
#include <petscvec.h>

#include "solver/block_smoother.hpp"
#include "solver/off_process_rows.hpp"
#include "solver/petsc_check.hpp"

namespace magfem::petsc_module {

// A vector's local values for a scope, given back however the scope ends (an error in the
// sweep, too).
class ReadArray {
public:
  explicit ReadArray(Vec v) : v_(v) { check(VecGetArrayRead(v_, &values_), "VecGetArrayRead"); }
  ~ReadArray() { VecRestoreArrayRead(v_, &values_); }
  ReadArray(const ReadArray&) = delete;
  ReadArray& operator=(const ReadArray&) = delete;
  const PetscScalar* data() const { return values_; }

private:
  Vec v_;
  const PetscScalar* values_ = nullptr;
};

class WriteArray {
public:
  explicit WriteArray(Vec v) : v_(v) { check(VecGetArray(v_, &values_), "VecGetArray"); }
  ~WriteArray() { VecRestoreArray(v_, &values_); }
  WriteArray(const WriteArray&) = delete;
  WriteArray& operator=(const WriteArray&) = delete;
  PetscScalar* data() const { return values_; }

private:
  Vec v_;
  PetscScalar* values_ = nullptr;
};

// x <- `sweeps` smoothing steps (down: BlockSmoother's down splitting, else its transpose)
// on this process's rows of b and x. `off_process`: the rows' part in other processes'
// unknowns (distributed: collective; the smoother's last rows are its reading_rows()), or
// null (serial).
inline void smooth_sweeps(BlockSmoother& smoother, OffProcessRows* off_process, Vec b, Vec x,
                          bool down, bool zero_guess, PetscInt sweeps, int threads) {
  const ReadArray vb(b);
  if (!off_process || off_process->size() == 1) {
    const WriteArray vx(x);
    smoother.smooth(vb.data(), vx.data(), down, zero_guess, sweeps, threads);
    return;
  }
  const int size = off_process->size(), rank = off_process->rank();
  // b - A_off x with the other processes' values as they are now (collective).
  const auto rhs = [&] { return off_process->subtract_from(vb.data(), x); };
  for (PetscInt sweep = 0; sweep < sweeps; ++sweep) {
    const bool from_zero = zero_guess && sweep == 0;
    if (from_zero)
      check(VecSet(x, 0.0), "VecSet");
    if (down) {
      // From zero the other processes' values are zero too.
      const double* r = from_zero ? vb.data() : rhs();
      smoother.sweep_all_but_last(r, WriteArray(x).data(), true, from_zero, threads);
      for (int p = 0; p < size; ++p) {
        if (p > 0)
          r = rhs(); // process p reads the new values of processes < p
        if (p == rank)
          smoother.sweep_last(r, WriteArray(x).data(), true);
      }
    } else {
      for (int p = size - 1; p >= 0; --p) {
        const double* r = from_zero && p == size - 1 ? vb.data() : rhs();
        if (p == rank)
          smoother.sweep_last(r, WriteArray(x).data(), false);
      }
      // The block may read the others' new values. (The gather reads x: before x's array is
      // taken for the sweep.)
      const double* r = rhs();
      smoother.sweep_all_but_last(r, WriteArray(x).data(), false, false, threads);
    }
  }
}

} // namespace magfem::petsc_module
