#pragma once
// Inside the PETSc module: pmg's fine-level smoother as PETSc's Richardson applies it
// (petsc_ksp_solver.cpp), serial and distributed in one. Serially BlockSmoother sweeps the
// whole system. Distributed it sweeps the process's diagonal block in place, the other
// processes' unknowns held at their values from the start of each sweep (block Jacobi across
// the processes): b - A_off x (OffProcessRows) is then the block's right-hand side. That is
// Richardson's step x + M^-1 (b - A x), M the block's splitting, without forming b - A x over
// the whole matrix first (a product of the whole matrix per V-cycle).
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
// unknowns (distributed: collective), or null (serial: nothing to subtract).
inline void smooth_block_jacobi(BlockSmoother& smoother, OffProcessRows* off_process, Vec b, Vec x,
                                bool down, bool zero_guess, PetscInt sweeps, int threads) {
  const ReadArray vb(b);
  for (PetscInt sweep = 0; sweep < sweeps; ++sweep) {
    const bool from_zero = zero_guess && sweep == 0;
    // From zero the other processes' values are zero too. The gather reads x, so x's array
    // is taken after it.
    const double* rhs =
        from_zero || !off_process ? vb.data() : off_process->subtract_from(vb.data(), x);
    const WriteArray vx(x);
    smoother.smooth(rhs, vx.data(), down, from_zero, 1, threads);
  }
}

} // namespace magfem::petsc_module
