#pragma once
// Inside the PETSc module: the part of a process's rows of a distributed matrix (MPIAIJ) that
// reads other processes' unknowns, PETSc's off-diagonal block, applied on its own. pmg's
// distributed smoother (petsc_ksp_solver.cpp) sweeps Gauss-Seidel over the process's diagonal
// block in place, with the other processes' values from the start of the sweep: b - A_off x
// is then its right-hand side, and the sweep needs no residual b - A x over the whole matrix
// (one product of the whole matrix per V-cycle fewer).
#include <vector>

#include <petscmat.h>

namespace magfem::petsc_module {

class OffProcessRows {
public:
  // `a`: MPIAIJ (its off-diagonal block is read in place: `a` must outlive this), or SeqAIJ
  // (no other processes: nothing to subtract). Collective.
  explicit OffProcessRows(Mat a);
  ~OffProcessRows();
  OffProcessRows(const OffProcessRows&) = delete;
  OffProcessRows& operator=(const OffProcessRows&) = delete;

  // b - A_off x for this process's rows (`b` its local part): gathers x's values from the
  // other processes. Collective. Returns `b` itself when the process reads none.
  const double* subtract_from(const double* b, Vec x);

  // This process's rows that read other processes' unknowns (local numbers, ascending).
  std::vector<PetscInt> reading_rows() const;
  // The matrix's processes, and this one's place among them (1 and 0 for SeqAIJ).
  int size() const { return size_; }
  int rank() const { return rank_; }

private:
  void destroy();

  Mat off_ = nullptr;           // PETSc's, not ours
  VecScatter gather_ = nullptr; // x -> the values the off-diagonal columns stand for
  Vec values_ = nullptr;        // ... sequential, one per off-diagonal column
  Vec product_ = nullptr;       // A_off values, one per local row
  std::vector<double> rhs_;
  int size_ = 1, rank_ = 0;
};

} // namespace magfem::petsc_module
