#include "solver/off_process_rows.hpp"

#include "solver/petsc_check.hpp"

namespace magfem::petsc_module {

OffProcessRows::OffProcessRows(Mat a) {
  PetscBool is_mpi = PETSC_FALSE;
  check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(a), MATMPIAIJ, &is_mpi),
        "PetscObjectTypeCompare");
  if (!is_mpi)
    return;
  MPI_Comm comm = MPI_COMM_NULL;
  check(PetscObjectGetComm(reinterpret_cast<PetscObject>(a), &comm), "PetscObjectGetComm");
  MPI_Comm_size(comm, &size_);
  MPI_Comm_rank(comm, &rank_);
  Mat diag = nullptr;
  const PetscInt* columns = nullptr; // the global column of each off-diagonal one
  check(MatMPIAIJGetSeqAIJ(a, &diag, &off_, &columns), "MatMPIAIJGetSeqAIJ");
  PetscInt rows = 0, n_off = 0;
  check(MatGetSize(off_, &rows, &n_off), "MatGetSize");
  IS from = nullptr;
  Vec x = nullptr;
  try {
    check(ISCreateGeneral(PETSC_COMM_SELF, n_off, columns, PETSC_COPY_VALUES, &from),
          "ISCreateGeneral");
    check(MatCreateVecs(a, &x, nullptr), "MatCreateVecs");
    check(VecCreateSeq(PETSC_COMM_SELF, n_off, &values_), "VecCreateSeq");
    check(VecCreateSeq(PETSC_COMM_SELF, rows, &product_), "VecCreateSeq");
    check(VecScatterCreate(x, from, values_, nullptr, &gather_), "VecScatterCreate");
  } catch (...) {
    ISDestroy(&from);
    VecDestroy(&x);
    destroy();
    throw;
  }
  ISDestroy(&from);
  VecDestroy(&x);
  rhs_.resize(static_cast<std::size_t>(rows));
}

OffProcessRows::~OffProcessRows() {
  destroy();
}

void OffProcessRows::destroy() {
  VecScatterDestroy(&gather_);
  VecDestroy(&values_);
  VecDestroy(&product_);
}

const double* OffProcessRows::subtract_from(const double* b, Vec x) {
  if (!off_)
    return b;
  check(VecScatterBegin(gather_, x, values_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(gather_, x, values_, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  check(MatMult(off_, values_, product_), "MatMult (off-diagonal block)");
  const PetscScalar* p = nullptr;
  check(VecGetArrayRead(product_, &p), "VecGetArrayRead");
  for (std::size_t i = 0; i < rhs_.size(); ++i)
    rhs_[i] = b[i] - p[i];
  check(VecRestoreArrayRead(product_, &p), "VecRestoreArrayRead");
  return rhs_.data();
}

std::vector<PetscInt> OffProcessRows::reading_rows() const {
  std::vector<PetscInt> rows;
  if (!off_)
    return rows;
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscScalar* v = nullptr;
  PetscMemType memory = PETSC_MEMTYPE_HOST;
  check(MatSeqAIJGetCSRAndMemType(off_, &ia, &ja, &v, &memory), "MatSeqAIJGetCSRAndMemType");
  for (PetscInt i = 0; i < static_cast<PetscInt>(rhs_.size()); ++i)
    if (ia[i + 1] > ia[i])
      rows.push_back(i);
  return rows;
}

} // namespace magfem::petsc_module
