#include "solver/petsc_ksp_solver.hpp"

#include <petscksp.h>

#include <Eigen/CholmodSupport>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <future>
#include <malloc.h>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>
#include <type_traits>
#include <vector>

#include "core/default_init_vector.hpp"
#include "core/input_error.hpp"
#include "core/progress.hpp"
#include "core/thread_count.hpp"
#include "solver/block_smoother.hpp"
#include "solver/csr_product.hpp"
#include "solver/distributed_galerkin_product.hpp"
#include "solver/full_csr.hpp"
#include "solver/galerkin_product.hpp"
#include "solver/mpi_world_backend.hpp"
#include "solver/off_process_rows.hpp"
#include "solver/own_row_matrix.hpp"
#include "solver/petsc_check.hpp"
#include "solver/pmg_partition.hpp"
#include "solver/simultaneous_pcg.hpp"
#include "solver/singleton_session_dir.hpp"
#include "solver/smoother_sweeps.hpp"

namespace magfem::petsc_module {
namespace {

// PETSc's own words for its last error ("Unable to find requested PC type nonsense"), which
// its error code alone does not carry. Written and read under petsc_mutex().
std::string& last_petsc_message() {
  static std::string message;
  return message;
}

PetscErrorCode record_error(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                            PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL)
    last_petsc_message() = message ? message : "";
  return code;
}

} // namespace

void check(PetscErrorCode code, const char* what) {
  if (code == 0)
    return;
  std::string text = last_petsc_message();
  if (text.empty()) {
    const char* generic = nullptr;
    PetscErrorMessage(code, &generic, nullptr);
    text = generic ? generic : "";
  }
  last_petsc_message().clear();
  throw SolveError(std::string("PETSc: ") + what + " failed" + (text.empty() ? "" : ": " + text));
}

namespace {

// PETSc and MPI for the life of the process, started on first use so that runs that never
// need AMG (2D, small 3D) never pay MPI's start-up.
class PetscSession {
public:
  PetscSession() {
    PetscBool already = PETSC_FALSE;
    PetscInitialized(&already);
    if (already)
      return;
    // A process started without mpirun is an MPI singleton. Open MPI then probes for a
    // runtime daemon and every network transport: 1.7 s measured here, against 0.45 s when
    // told it is alone (one process needs only the self transport). Set only if unset, and
    // never under mpirun, which exports OMPI_COMM_WORLD_SIZE.
    if (!std::getenv("OMPI_COMM_WORLD_SIZE")) {
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
      setenv("OMPI_MCA_pml", "ob1", 0);
      setenv("OMPI_MCA_btl", "self,vader", 0);
    }
    // Our own crash is ours to report; PETSc's handler would print its own trace instead.
    PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
    check(PetscInitializeNoArguments(), "PetscInitialize");
    owned_ = true;
    // Errors come back as codes and become SolveError here, without PETSc's stderr trace.
    PetscPushErrorHandler(record_error, nullptr);
  }
  ~PetscSession() {
    if (owned_)
      PetscFinalize();
  }
  PetscSession(const PetscSession&) = delete;
  PetscSession& operator=(const PetscSession&) = delete;

private:
  // Declared first: created before MPI starts, removed after PetscFinalize (members are
  // destroyed after the destructor's body).
  SingletonSessionDir session_dir_;
  bool owned_ = false;
};

void ensure_petsc() {
  static PetscSession session;
}

// PETSc (as Debian builds it) is not thread-safe, and a sweep solves positions on several
// threads: one PETSc call sequence at a time per process.
std::mutex& petsc_mutex() {
  static std::mutex m;
  return m;
}

// Our defaults per preconditioner, before the user's options. BoomerAMG: HMIS coarsening with
// extended+i interpolation (at most 4 weights per row) and a strength threshold of 0.5, the
// settings hypre recommends for 3D operators: the classical 0.25 with Falgout coarsening keeps
// too many points on P2 tetrahedra and the hierarchy becomes expensive.
std::string boomeramg_options(const std::string& prefix) {
  return "-" + prefix + "pc_hypre_boomeramg_coarsen_type HMIS -" + prefix +
         "pc_hypre_boomeramg_interp_type ext+i -" + prefix + "pc_hypre_boomeramg_P_max 4 -" +
         prefix + "pc_hypre_boomeramg_strong_threshold 0.5";
}

std::string default_options(const std::string& preconditioner) {
  if (preconditioner == "boomeramg")
    return boomeramg_options("");
  // p-multigrid: BoomerAMG on the coarse (P1) level, where it fits (a nodal Laplacian-like
  // operator).
  if (preconditioner == "pmg")
    return boomeramg_options("mg_coarse_");
  return "";
}

// PETSc's objects read the options database they were given; the sub-solvers PCMG creates
// would otherwise read the global one and miss petsc_options.
void use_options(KSP ksp, PetscOptions db) {
  check(PetscObjectSetOptions(reinterpret_cast<PetscObject>(ksp), db), "options");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PetscObjectSetOptions(reinterpret_cast<PetscObject>(pc), db), "options");
}

// A multigrid level smoother: one Richardson step of its preconditioner (set by the caller).
PC one_sweep_smoother(KSP smoother, PetscOptions db) {
  use_options(smoother, db);
  check(KSPSetType(smoother, KSPRICHARDSON), "KSPSetType(richardson)");
  check(KSPSetTolerances(smoother, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 1),
        "KSPSetTolerances (smoother)");
  PC pc = nullptr;
  check(KSPGetPC(smoother, &pc), "KSPGetPC");
  return pc;
}

} // namespace

void start_petsc(bool any_thread_calls_mpi) {
  const std::lock_guard lock(petsc_mutex());
  // PETSc asks MPI for MPI_THREAD_FUNNELED unless told otherwise; the thread level is fixed
  // when MPI starts, so it is chosen here, before the first PETSc call.
  if (any_thread_calls_mpi)
    PETSC_MPI_THREAD_REQUIRED = MPI_THREAD_MULTIPLE;
  ensure_petsc();
}

namespace {

// The block smoother is built when PETSc sets the smoothers up, not before: options that
// replace it (-mg_levels_pc_type sor, the one-sweep SSOR smoother of before) then cost no
// factorization. Down and up share it. Serially without petsc_options nothing can replace it:
// its block's factorization starts in setup() from the lower triangle (block_factoring), and
// the rest of it is built on a thread of its own (`building`) from the start of pmg's set-up,
// while the full CSR, the Galerkin product and BoomerAMG's set-up are made: the CHOLMOD
// analysis (METIS) and BoomerAMG's set-up are each serial (benchmark32: 1.4 and ~1.2 s of CPU,
// the factor 3.7 s on two BLAS threads). The smoother is the same either way: the block's
// lower triangle is the same matrix from either form, and nothing writes the arrays meanwhile.
struct BlockSmootherSlot {
  CsrView matrix;
  const std::vector<int>* block = nullptr;
  BlockFactorCache* cache = nullptr;
  std::unique_ptr<BlockSmoother> smoother;
  std::future<std::unique_ptr<BlockSmoother>> building; // joined after KSPSetUp
  std::unique_ptr<OffProcessRows> off_process;          // distributed only
  std::vector<PetscInt> last;                           // off_process's reading_rows()
};

std::unique_ptr<BlockSmoother> make_block_smoother(const BlockSmootherSlot& slot,
                                                   std::shared_ptr<const BlockFactor> factor) {
  auto smoother = factor ? std::make_unique<BlockSmoother>(slot.matrix, *slot.block, factor)
                         : std::make_unique<BlockSmoother>(slot.matrix, *slot.block, *slot.cache);
  smoother->put_last(slot.last);
  return smoother;
}

PetscErrorCode set_up_block_smoother(PC pc) {
  void* context = nullptr;
  PetscCall(PCShellGetContext(pc, &context));
  auto& slot = *static_cast<BlockSmootherSlot*>(context);
  if (slot.smoother || slot.building.valid())
    return 0;
  try {
    slot.smoother = make_block_smoother(slot, nullptr);
  } catch (const std::exception& e) { // no exception through PETSc's C frames
    return PetscError(PETSC_COMM_SELF, __LINE__, "set_up_block_smoother", __FILE__, PETSC_ERR_LIB,
                      PETSC_ERROR_INITIAL, "%s", e.what());
  }
  return 0;
}

// PCShellSetApplyRichardson's callback.
using RichardsonStep = PetscErrorCode (*)(PC, Vec, Vec, Vec, PetscReal, PetscReal, PetscReal,
                                          PetscInt, PetscBool, PetscInt*,
                                          PCRichardsonConvergedReason*);

// Richardson's smoothing steps (smoother_sweeps.hpp): serially over the whole system,
// distributed over the process's rows, process after process (the slot's off_process).
template <bool Down>
PetscErrorCode smooth_richardson(PC pc, Vec b, Vec x, Vec, PetscReal, PetscReal, PetscReal,
                                 PetscInt its, PetscBool zero_guess, PetscInt* done,
                                 PCRichardsonConvergedReason* reason) {
  void* context = nullptr;
  PetscCall(PCShellGetContext(pc, &context));
  auto& slot = *static_cast<BlockSmootherSlot*>(context);
  try {
    smooth_sweeps(*slot.smoother, slot.off_process.get(), b, x, Down, zero_guess, its,
                  available_threads());
  } catch (const std::exception& e) { // no exception through PETSc's C frames
    return PetscError(PETSC_COMM_SELF, __LINE__, "smooth_richardson", __FILE__, PETSC_ERR_LIB,
                      PETSC_ERROR_INITIAL, "%s", e.what());
  }
  *done = its;
  *reason = PCRICHARDSON_CONVERGED_ITS;
  return 0;
}

// Distributed without a block: one symmetric Gauss-Seidel sweep (down, then up) before and
// after the coarse correction, as PETSc's SSOR does serially, over all processes' rows
// (smoother_sweeps.hpp); PETSc's SOR on MPIAIJ would be local SSOR, block Jacobi across the
// processes.
PetscErrorCode smooth_richardson_symmetric(PC pc, Vec b, Vec x, Vec, PetscReal, PetscReal,
                                           PetscReal, PetscInt its, PetscBool zero_guess,
                                           PetscInt* done, PCRichardsonConvergedReason* reason) {
  void* context = nullptr;
  PetscCall(PCShellGetContext(pc, &context));
  auto& slot = *static_cast<BlockSmootherSlot*>(context);
  try {
    for (PetscInt it = 0; it < its; ++it) {
      smooth_sweeps(*slot.smoother, slot.off_process.get(), b, x, true, zero_guess && it == 0, 1,
                    available_threads());
      smooth_sweeps(*slot.smoother, slot.off_process.get(), b, x, false, false, 1,
                    available_threads());
    }
  } catch (const std::exception& e) { // no exception through PETSc's C frames
    return PetscError(PETSC_COMM_SELF, __LINE__, "smooth_richardson_symmetric", __FILE__,
                      PETSC_ERR_LIB, PETSC_ERROR_INITIAL, "%s", e.what());
  }
  *done = its;
  *reason = PCRICHARDSON_CONVERGED_ITS;
  return 0;
}

// M^-1 b from x = 0 (the smoother as a preconditioner of another Krylov method).
PetscErrorCode smooth_apply_symmetric(PC pc, Vec b, Vec x) {
  PetscInt done = 0;
  PCRichardsonConvergedReason reason;
  return smooth_richardson_symmetric(pc, b, x, nullptr, 0, 0, 0, 1, PETSC_TRUE, &done, &reason);
}

template <bool Down> PetscErrorCode smooth_apply(PC pc, Vec b, Vec x) {
  PetscInt done = 0;
  PCRichardsonConvergedReason reason;
  return smooth_richardson<Down>(pc, b, x, nullptr, 0, 0, 0, 1, PETSC_TRUE, &done, &reason);
}

// y = A x for the MATSHELL over our CSR arrays (PetscKspSolver::setup).
PetscErrorCode multiply_csr(Mat a, Vec x, Vec y) {
  void* context = nullptr;
  PetscCall(MatShellGetContext(a, &context));
  const PetscScalar* vx = nullptr;
  PetscScalar* vy = nullptr;
  PetscCall(VecGetArrayRead(x, &vx));
  PetscCall(VecGetArrayWrite(y, &vy));
  csr_multiply(*static_cast<const CsrView*>(context), vx, vy, available_threads());
  PetscCall(VecRestoreArrayWrite(y, &vy));
  PetscCall(VecRestoreArrayRead(x, &vx));
  return 0;
}

} // namespace

// galerkin_product and our CSR arrays share PETSc's index type (Debian's PETSc: 32-bit).
static_assert(std::is_same_v<PetscInt, int>);

struct PetscKspSolver::Impl {
  PetscSolverOptions options;
  PetscOptions db = nullptr;
  KSP ksp = nullptr;
  Mat a = nullptr;
  // Serial pmg without petsc_options: the operator of CG's products and PCMG's fine residual
  // (two per iteration, a third of CG's time at benchmark32) as a MATSHELL over `a`'s arrays
  // multiplying on all cores; PETSc's own product is serial. `a` stays the matrix the
  // preconditioner is built from.
  Mat product = nullptr;
  CsrView product_matrix;
  Mat p = nullptr;      // pmg's interpolation
  Mat coarse = nullptr; // pmg's coarse operator P^T A P
  Vec rhs = nullptr;    // distributed mode: the right-hand side of the solve
  std::unique_ptr<BlockSmootherSlot> block_smoother; // pmg with a smoother block
  BlockFactorCache block_factor;                     // kept across setup() calls (not release()d)
  // Serial pmg: the block's factorization, started by setup() from the lower triangle before
  // the full CSR is built (joined by the smoother's build; declared after block_factor, which
  // it writes, so that it is joined first).
  std::future<std::shared_ptr<const BlockFactor>> block_factoring;
  std::vector<PetscInt> row_start, p_row_start, p_column;
  DefaultInitVector<PetscInt> column; // filled on all cores (to_full_csr), so not zeroed first
  DefaultInitVector<PetscScalar> value;
  std::vector<PetscScalar> p_value;
  CsrMatrix coarse_csr; // the arrays behind `coarse`
  double rhs_norm = 1;
  // Distributed mode (begin_distributed): `a` is one MPIAIJ matrix over MPI_COMM_WORLD, and
  // for pmg diag_block this process's diagonal block of it (PETSc's arrays), local_block the
  // smoother block's equations among its rows (local numbering).
  bool distributed = false;
  bool factor_on_node_cores = false; // start_distributed_block_factor
  bool block_factor_started = false; // by assemble_own_rows, before the matrix is built
  CsrView diag_block;
  std::vector<int> local_block;
  // Distributed pmg: the rows each process owns (pmg_partition.hpp): options.rows when given
  // (own-row assembly: not copied, the caller keeps it), else computed_partition. Empty: rows
  // are equations, in contiguous blocks.
  PmgPartition computed_partition;
  const PmgPartition* partition_in_use = &computed_partition;
  const PmgPartition& partition() const { return *partition_in_use; }

  ~Impl() {
    release();
    if (db)
      PetscOptionsDestroy(&db);
  }
  void release() {
    if (ksp)
      KSPDestroy(&ksp);
    if (a)
      MatDestroy(&a);
    if (product)
      MatDestroy(&product);
    if (p)
      MatDestroy(&p);
    if (coarse)
      MatDestroy(&coarse);
    if (rhs)
      VecDestroy(&rhs);
    block_smoother.reset();
    block_factoring = {}; // waits for a factorization still running
    block_factor_started = false;
    diag_block = {}; // pointed into `a`
  }
  void to_full_csr(const Eigen::SparseMatrix<double>& lower);
  void set_up_ksp(MPI_Comm comm);
  KrylovOutcome outcome(double rhs_norm) const;
  void set_up_pmg(PC pc);
  void make_block_smoother_slot(const std::vector<int>* block,
                                std::unique_ptr<OffProcessRows> off_process = nullptr);
  void use_shell_smoother(KSP smoother, const char* name, RichardsonStep richardson,
                          PetscErrorCode (*apply)(PC, Vec, Vec)) const;
  PetscInt row_of(PetscInt equation) const {
    return partition().order.empty() ? equation : partition().order[equation];
  }
  // `row`: one this process owns.
  PetscInt equation_of(PetscInt row) const {
    const PmgPartition& rows = partition();
    return rows.order.empty() ? row : rows.local_equations[row - rows.own_begin];
  }
  // pmg's fine matrix for the smoother: serially the whole (row_start, column, value),
  // distributed this process's diagonal block.
  CsrView fine_matrix() const {
    if (distributed)
      return diag_block;
    return {static_cast<PetscInt>(row_start.size()) - 1, row_start.data(), column.data(),
            value.data()};
  }
  void set_up_serial_coarse_space(const Eigen::SparseMatrix<double, Eigen::RowMajor>& q);
  void set_up_distributed_coarse_space(const Eigen::SparseMatrix<double, Eigen::RowMajor>& q);
  void take_diagonal_block();
  void start_distributed_block_factor(const Eigen::SparseMatrix<double>* own_rows);
  bool runs_block_vcycle() const;
  void multiply_many(const ColumnBlock& x, ColumnBlock& y) const;
  void vcycle_many(const ColumnBlock& r, ColumnBlock& z);
  static PetscErrorCode monitor(KSP, PetscInt it, PetscReal rnorm, void* self);
};

void PetscKspSolver::Impl::to_full_csr(const Eigen::SparseMatrix<double>& lower) {
  FullCsr full = full_csr_from_lower(lower);
  row_start = std::move(full.row_start);
  column = std::move(full.column);
  value = std::move(full.value);
}

// The smoother's slot for `block`; when the block's factorization is already under way
// (block_factoring), the smoother is built from it on a thread beside the rest of the set-up
// and joined by the shell's PCSetUp. Distributed, `off_process` and its rows are in the slot
// before that thread starts.
void PetscKspSolver::Impl::make_block_smoother_slot(const std::vector<int>* block,
                                                    std::unique_ptr<OffProcessRows> off_process) {
  block_smoother = std::make_unique<BlockSmootherSlot>(
      BlockSmootherSlot{fine_matrix(), block, &block_factor, nullptr, {}, nullptr, {}});
  if (off_process) {
    block_smoother->last = off_process->reading_rows();
    block_smoother->off_process = std::move(off_process);
  }
  if (block_factoring.valid())
    block_smoother->building = std::async(std::launch::async, [slot = block_smoother.get(), this] {
      return make_block_smoother(*slot, block_factoring.get());
    });
}

// `smoother` (one of PCMG's finest level) as one Richardson step of a PCSHELL over the block
// smoother's slot: `richardson` the step, `apply` the same from zero (PCApply).
void PetscKspSolver::Impl::use_shell_smoother(KSP smoother, const char* name,
                                              RichardsonStep richardson,
                                              PetscErrorCode (*apply)(PC, Vec, Vec)) const {
  PC shell = one_sweep_smoother(smoother, db);
  check(KSPSetNormType(smoother, KSP_NORM_NONE), "KSPSetNormType (smoother)");
  check(PCSetType(shell, PCSHELL), "PCSetType(shell)");
  check(PCShellSetContext(shell, block_smoother.get()), "PCShellSetContext");
  check(PCShellSetName(shell, name), "PCShellSetName");
  check(PCShellSetSetUp(shell, set_up_block_smoother), "PCShellSetSetUp");
  check(PCShellSetApplyRichardson(shell, richardson), "PCShellSetApplyRichardson");
  check(PCShellSetApply(shell, apply), "PCShellSetApply");
}

// Two-level p-multigrid as PETSc's PCMG: the given interpolation, the Galerkin coarse operator
// P^T A P (galerkin_product), one V-cycle per CG iteration, one fixed symmetric operator as CG
// needs. Smoother, with a smoother block (the open-boundary shell): block Gauss-Seidel
// (BlockSmoother above: the block by CHOLMOD and one Gauss-Seidel sweep over the rest, down
// and transposed up). Without one: one symmetric Gauss-Seidel sweep (SSOR, omega 1) before
// and after the coarse correction. Measured on the magnetized sphere (CG iterations at mesh
// scales 2.5 / 1.4 / 1, 255k / 488k / 942k unknowns): SSOR 73 / 98 / 122; two SSOR sweeps
// 59 / 80; Chebyshev over SSOR 44 / 61; an exact (CHOLMOD) coarse solve instead of one
// BoomerAMG V-cycle 67 at 2.5; ICC(0) as the smoother is indefinite; the shell by one
// BoomerAMG V-cycle instead of CHOLMOD 43 / 55; the shell by CHOLMOD 23 / 23 / 23, also
// faster (2.0 against 4.6 s of CG at 255k). The point smoothers all grow alike: the shell's
// anisotropy grows under refinement (BlockSmoother), which the P1 space cannot take up.
//
// Distributed (issue 33), the same two levels over MPI_COMM_WORLD: the interpolation and
// the coarse operator as MPIAIJ matrices (set_up_distributed_coarse_space), BoomerAMG on the
// coarse level, and as smoother the serial one over all processes' rows: Gauss-Seidel, each
// process over its diagonal block, the rows that read other processes' unknowns last and
// process after process (smoother_sweeps.hpp), the shell's equations (all on process 0)
// solved together by CHOLMOD. Without a shell, one symmetric Gauss-Seidel sweep over all
// processes' rows in the same order (smooth_richardson_symmetric), as the serial SSOR.
void PetscKspSolver::Impl::set_up_pmg(PC pc) {
  if (!options.prolongation)
    throw SolveError("internal: p-multigrid without a coarse space");
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& q = *options.prolongation;
  // The global block decides (every process must set the same smoother type up).
  const bool has_block = options.smoother_block && !options.smoother_block->empty();
  if (has_block && !distributed) {
    make_block_smoother_slot(options.smoother_block);
  }
  if (distributed)
    set_up_distributed_coarse_space(q);
  else
    set_up_serial_coarse_space(q);
  check(PCSetType(pc, PCMG), "PCSetType(mg)");
  check(PCMGSetLevels(pc, 2, nullptr), "PCMGSetLevels");
  check(PCMGSetType(pc, PC_MG_MULTIPLICATIVE), "PCMGSetType");
  check(PCMGSetCycleType(pc, PC_MG_CYCLE_V), "PCMGSetCycleType");
  check(PCMGSetInterpolation(pc, 1, p), "PCMGSetInterpolation");
  check(PCMGSetGalerkin(pc, PC_MG_GALERKIN_NONE), "PCMGSetGalerkin");
  KSP coarse_ksp = nullptr;
  if (has_block) {
    if (distributed) { // the process's diagonal block is known once the coarse space is
      make_block_smoother_slot(&local_block, std::make_unique<OffProcessRows>(a));
    }
    KSP down = nullptr, up = nullptr;
    check(PCMGGetSmootherDown(pc, 1, &down), "PCMGGetSmootherDown");
    check(PCMGGetSmootherUp(pc, 1, &up), "PCMGGetSmootherUp");
    use_shell_smoother(down, "block Gauss-Seidel", smooth_richardson<true>, smooth_apply<true>);
    use_shell_smoother(up, "block Gauss-Seidel", smooth_richardson<false>, smooth_apply<false>);
  } else if (distributed) {
    make_block_smoother_slot(&local_block, std::make_unique<OffProcessRows>(a));
    KSP smoother = nullptr; // down and up alike
    check(PCMGGetSmoother(pc, 1, &smoother), "PCMGGetSmoother");
    use_shell_smoother(smoother, "symmetric Gauss-Seidel", smooth_richardson_symmetric,
                       smooth_apply_symmetric);
  } else {
    KSP smoother = nullptr;
    check(PCMGGetSmoother(pc, 1, &smoother), "PCMGGetSmoother");
    PC smoother_pc = one_sweep_smoother(smoother, db);
    check(PCSetType(smoother_pc, PCSOR), "PCSetType(sor)");
    check(PCSORSetSymmetric(smoother_pc, SOR_LOCAL_SYMMETRIC_SWEEP), "PCSORSetSymmetric");
  }
  check(PCMGGetCoarseSolve(pc, &coarse_ksp), "PCMGGetCoarseSolve");
  use_options(coarse_ksp, db);
  check(KSPSetOperators(coarse_ksp, coarse, coarse), "KSPSetOperators (coarse)");
  check(KSPSetType(coarse_ksp, KSPPREONLY), "KSPSetType(preonly)");
  PC coarse_pc = nullptr;
  check(KSPGetPC(coarse_ksp, &coarse_pc), "KSPGetPC");
  check(PCSetType(coarse_pc, PCHYPRE), "PCSetType(hypre)");
  check(PCHYPRESetType(coarse_pc, "boomeramg"), "PCHYPRESetType");
}

// Serial: the interpolation over the caller's arrays, and the Galerkin operator by our
// row-wise product (galerkin_product.hpp), not PETSc's general one: the same matrix, a fifth
// of the time.
void PetscKspSolver::Impl::set_up_serial_coarse_space(
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& q) {
  if (q.rows() != static_cast<Eigen::Index>(row_start.size()) - 1 || !q.isCompressed())
    throw SolveError("internal: the coarse space does not fit the system");
  p_row_start.assign(q.outerIndexPtr(), q.outerIndexPtr() + q.rows() + 1);
  p_column.assign(q.innerIndexPtr(), q.innerIndexPtr() + q.nonZeros());
  p_value.assign(q.valuePtr(), q.valuePtr() + q.nonZeros());
  check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, static_cast<PetscInt>(q.rows()),
                                  static_cast<PetscInt>(q.cols()), p_row_start.data(),
                                  p_column.data(), p_value.data(), &p),
        "MatCreateSeqAIJWithArrays (interpolation)");
  coarse_csr = galerkin_product(row_start.data(), column.data(), value.data(), q);
  check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, coarse_csr.rows, coarse_csr.cols,
                                  coarse_csr.row_start.data(), coarse_csr.column.data(),
                                  coarse_csr.value.data(), &coarse),
        "MatCreateSeqAIJWithArrays (coarse operator)");
}

// Distributed: every process holds the whole interpolation `q` and puts its own rows (those
// it owns of the fine matrix) into an MPIAIJ matrix. The columns (the P1 unknowns) are split
// evenly over the processes rather than following the fine rows of their vertices: the DOF
// numbering puts the vertices first, so with rows in contiguous blocks the first process
// would own every P1 unknown and do the whole coarse level alone. The coarse operator
// P^T A P by distributed_galerkin_product (each process its rows' share). Then the smoother's
// diagonal block (take_diagonal_block), unless start_distributed_block_factor took it already.
void PetscKspSolver::Impl::set_up_distributed_coarse_space(
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& q) {
  PetscInt n = 0, begin = 0, end = 0;
  check(MatGetSize(a, &n, nullptr), "MatGetSize");
  const PmgPartition& partition = this->partition();
  if (q.rows() != n || !q.isCompressed() || partition.order.size() != static_cast<std::size_t>(n))
    throw SolveError("internal: the coarse space does not fit the system");
  check(MatGetOwnershipRange(a, &begin, &end), "MatGetOwnershipRange");
  const auto m = static_cast<PetscInt>(q.cols());
  PetscInt c_end = 0;
  const PetscInt coarse_local = partition.coarse_local;
  MPI_Scan(&coarse_local, &c_end, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  const PetscInt c_begin = c_end - coarse_local;
  const int* q_start = q.outerIndexPtr();
  const int* q_column = q.innerIndexPtr();
  std::vector<PetscInt> in_block(end - begin, 0), off_block(end - begin, 0);
  for (PetscInt r = begin; r < end; ++r) {
    const PetscInt i = equation_of(r);
    for (int k = q_start[i]; k < q_start[i + 1]; ++k) {
      const PetscInt c = partition.coarse_order[q_column[k]];
      ++(c >= c_begin && c < c_end ? in_block : off_block)[r - begin];
    }
  }
  check(MatCreateAIJ(PETSC_COMM_WORLD, end - begin, coarse_local, n, m, 0, in_block.data(), 0,
                     off_block.data(), &p),
        "MatCreateAIJ (interpolation)");
  std::vector<PetscInt> columns;
  for (PetscInt r = begin; r < end; ++r) {
    const PetscInt i = equation_of(r);
    columns.clear();
    for (int k = q_start[i]; k < q_start[i + 1]; ++k)
      columns.push_back(partition.coarse_order[q_column[k]]);
    check(MatSetValues(p, 1, &r, static_cast<PetscInt>(columns.size()), columns.data(),
                       q.valuePtr() + q_start[i], INSERT_VALUES),
          "MatSetValues (interpolation)");
  }
  check(MatAssemblyBegin(p, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin (interpolation)");
  check(MatAssemblyEnd(p, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd (interpolation)");
  coarse = distributed_galerkin_product(a, q, partition, c_begin, c_end);
  // The product's scratch pages given back now: the shell's factor, running meanwhile on a
  // thread of its own (start_distributed_block_factor), allocates in that thread's arena, not
  // in the pages freed here (benchmark32, process 0, with PETSc's MatPtAP: 2.35 GB at the peak
  // without this, 1.87 GB with it).
  malloc_trim(0);

  if (!diag_block.row_start)
    take_diagonal_block();
}

// The process's diagonal block of `a` (its rows, its columns) into diag_block for the smoother,
// and the smoother block's equations among its rows into local_block.
void PetscKspSolver::Impl::take_diagonal_block() {
  PetscInt begin = 0, end = 0;
  check(MatGetOwnershipRange(a, &begin, &end), "MatGetOwnershipRange");
  Mat diag = a, off = nullptr;
  const PetscInt* off_columns = nullptr;
  PetscBool is_mpi = PETSC_FALSE;
  check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(a), MATMPIAIJ, &is_mpi),
        "PetscObjectTypeCompare");
  if (is_mpi)
    check(MatMPIAIJGetSeqAIJ(a, &diag, &off, &off_columns), "MatMPIAIJGetSeqAIJ");
  // Read in place: the arrays stay valid while `a` lives, which the smoother does not outlive
  // (release()).
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscScalar* v = nullptr;
  PetscMemType memory = PETSC_MEMTYPE_HOST;
  check(MatSeqAIJGetCSRAndMemType(diag, &ia, &ja, &v, &memory), "MatSeqAIJGetCSRAndMemType");
  if (memory != PETSC_MEMTYPE_HOST)
    throw SolveError("internal: the diagonal block is not in host memory");
  diag_block = {end - begin, ia, ja, v};
  local_block.clear();
  if (options.smoother_block)
    for (int e : *options.smoother_block)
      if (const PetscInt r = row_of(e); r >= begin && r < end)
        local_block.push_back(r - begin);
  std::sort(local_block.begin(), local_block.end());
}

PetscErrorCode PetscKspSolver::Impl::monitor(KSP, PetscInt it, PetscReal rnorm, void* self) {
  auto* impl = static_cast<Impl*>(self);
  if (impl->options.progress)
    impl->options.progress->iteration(("CG+" + impl->options.preconditioner).c_str(),
                                      static_cast<int>(it), rnorm / impl->rhs_norm);
  return 0;
}

PetscKspSolver::PetscKspSolver(PetscSolverOptions options) : impl_(std::make_unique<Impl>()) {
  const std::lock_guard lock(petsc_mutex());
  ensure_petsc();
  impl_->options = std::move(options);
  check(PetscOptionsCreate(&impl_->db), "PetscOptionsCreate");
  const std::string all =
      default_options(impl_->options.preconditioner) + " " + impl_->options.petsc_options;
  check(PetscOptionsInsertString(impl_->db, all.c_str()), "reading the PETSc options");
}

PetscKspSolver::~PetscKspSolver() {
  const std::lock_guard lock(petsc_mutex());
  impl_.reset();
}

// CG with our tolerance and the preconditioner on `a`, then the user's options.
void PetscKspSolver::Impl::set_up_ksp(MPI_Comm comm) {
  check(KSPCreate(comm, &ksp), "KSPCreate");
  check(PetscObjectSetOptions(reinterpret_cast<PetscObject>(ksp), db), "options");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PetscObjectSetOptions(reinterpret_cast<PetscObject>(pc), db), "options");
  check(KSPSetOperators(ksp, product ? product : a, a), "KSPSetOperators");
  check(KSPSetType(ksp, KSPCG), "KSPSetType");
  // The unpreconditioned residual: the same test as the incomplete-Cholesky CG, so the
  // tolerance means the same whichever preconditioner ran.
  check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  check(
      KSPSetTolerances(ksp, options.relative_tolerance, 0.0, PETSC_DEFAULT, options.max_iterations),
      "KSPSetTolerances");
  if (options.preconditioner == "pmg") {
    set_up_pmg(pc);
  } else if (options.preconditioner == "gamg") {
    check(PCSetType(pc, PCGAMG), "PCSetType(gamg)");
  } else {
    check(PCSetType(pc, PCHYPRE), "PCSetType(hypre)");
    check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
  }
  check(KSPSetFromOptions(ksp), "applying petsc_options");
  check(KSPMonitorSet(ksp, &Impl::monitor, this, nullptr), "KSPMonitorSet");
  check(KSPSetUp(ksp), "preconditioner set-up");
  if (block_smoother && block_smoother->building.valid())
    block_smoother->smoother = block_smoother->building.get(); // rethrows the build's error
  // The processes without the shell wait here for process 0's factor, sleeping, so that its
  // BLAS threads have their cores (start_distributed_block_factor).
  if (distributed && factor_on_node_cores)
    idle_barrier();
}

// Distributed pmg: process 0, which owns the open-boundary shell (pmg_partition.hpp), factors
// it on a thread beside the rest of the set-up (the coarse space, the Galerkin product and
// BoomerAMG's set-up), as the serial set-up does; and on every core of its machine, with as
// many BLAS threads, since the other processes, their share of the set-up done, wait for it
// in set_up_ksp's idle barrier. With own-row assembly (`own_rows`: this process's lower
// triangle, its rows whole) the block is complete in it before the MPIAIJ matrix exists, and
// in the diagonal block's order (a process's rows follow its equations' order), so the factor
// starts before own_row_matrix; else from the assembled matrix's diagonal block. Collective.
void PetscKspSolver::Impl::start_distributed_block_factor(
    const Eigen::SparseMatrix<double>* own_rows) {
  factor_on_node_cores = false;
  if (options.preconditioner != "pmg" || !options.petsc_options.empty() ||
      !options.concurrent_block_factor || !options.smoother_block ||
      options.smoother_block->empty())
    return;
  const cpu_set_t cores = node_cores();
  factor_on_node_cores = true;
  Eigen::SparseMatrix<double> block;
  if (own_rows) {
    std::vector<int> own; // the block's equations among this process's rows, ascending
    for (int e : *options.smoother_block)
      if (partition().owns(e))
        own.push_back(e);
    std::sort(own.begin(), own.end());
    if (own.empty())
      return;
    block = block_lower_triangle(*own_rows, own);
  } else {
    take_diagonal_block();
    if (local_block.empty())
      return;
    block = block_lower_triangle(diag_block, block_places(diag_block.rows, local_block));
  }
  block_factoring =
      std::async(std::launch::async, [&cache = block_factor, lower = std::move(block), cores] {
        const ThreadOnCores on(cores);
        const BlasThreads blas(std::max(1, CPU_COUNT(&cores)));
        return factorize_block(lower, cache);
      });
}

void PetscKspSolver::setup(const Eigen::SparseMatrix<double>& lower) {
  const std::lock_guard lock(petsc_mutex());
  Impl& m = *impl_;
  m.release();
  m.distributed = false;
  // The smoother block's factorization (the longest part of the set-up: METIS and CHOLMOD,
  // 4 s at benchmark32) from the lower triangle, beside the full CSR, the Galerkin product
  // and BoomerAMG's set-up. Only where nothing can replace the block smoother.
  if (m.options.preconditioner == "pmg" && m.options.petsc_options.empty() &&
      m.options.concurrent_block_factor && m.options.smoother_block &&
      !m.options.smoother_block->empty())
    m.block_factoring = std::async(
        std::launch::async, [&cache = m.block_factor,
                             block_lower = block_lower_triangle(lower, *m.options.smoother_block)] {
          return factorize_block(block_lower, cache);
        });
  m.to_full_csr(lower);
  const auto n = static_cast<PetscInt>(lower.rows());
  check(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n, n, m.row_start.data(), m.column.data(),
                                  m.value.data(), &m.a),
        "MatCreateSeqAIJWithArrays");
  if (m.options.preconditioner == "pmg" && m.options.petsc_options.empty() &&
      m.options.threaded_product) {
    m.product_matrix = m.fine_matrix();
    check(MatCreateShell(PETSC_COMM_SELF, n, n, n, n, &m.product_matrix, &m.product),
          "MatCreateShell");
    check(
        MatShellSetOperation(m.product, MATOP_MULT, reinterpret_cast<void (*)(void)>(multiply_csr)),
        "MatShellSetOperation");
  }
  m.set_up_ksp(PETSC_COMM_SELF);
}

KrylovOutcome PetscKspSolver::solve(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  Impl& m = *impl_;
  KrylovOutcome out;
  const auto n = static_cast<PetscInt>(rhs.size());
  x = Eigen::VectorXd::Zero(rhs.size());
  m.rhs_norm = rhs.norm();
  if (m.rhs_norm == 0) {
    out.converged = true;
    out.reason = "zero right-hand side";
    return out;
  }
  Eigen::VectorXd b = rhs;
  const std::lock_guard lock(petsc_mutex());
  Vec vb = nullptr, vx = nullptr;
  check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, b.data(), &vb), "VecCreateSeqWithArray");
  check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, x.data(), &vx), "VecCreateSeqWithArray");
  // OpenBLAS on one thread for CG: CHOLMOD's triangular solves in the V-cycles gain little
  // from a second one, and between calls idle OpenBLAS threads spin (sched_yield) on the core
  // the product's second thread needs (benchmark32: sys time 13.9 -> 3.9 s, one run each).
  // The factorization, in the set-up, keeps every thread.
  const BlasThreads one_blas_thread(1);
  const PetscErrorCode code = KSPSolve(m.ksp, vb, vx);
  VecDestroy(&vb);
  VecDestroy(&vx);
  check(code, "KSPSolve");
  return m.outcome(m.rhs_norm);
}

// Our V-cycle is PCMG's (set_up_pmg) only while no petsc_options could have changed PCMG's
// smoothers, cycle or coarse solve.
bool PetscKspSolver::Impl::runs_block_vcycle() const {
  return options.preconditioner == "pmg" && options.petsc_options.empty() && block_smoother &&
         block_smoother->smoother;
}

void PetscKspSolver::Impl::multiply_many(const ColumnBlock& x, ColumnBlock& y) const {
  const CsrView a = fine_matrix();
  y.setZero(x.rows(), x.cols());
  for (PetscInt i = 0; i < a.rows; ++i)
    subtract_row_products(a.row_start, a.column, a.value, i, x,
                          y.data() + static_cast<Eigen::Index>(i) * x.cols());
  y = -y;
}

// One V-cycle of pmg (PCMG multiplicative, as set_up_pmg builds it) on every column of r:
// the block smoother down from z = 0, the coarse correction of the residual (BoomerAMG, one
// column at a time: the P1 level is small), the block smoother up.
void PetscKspSolver::Impl::vcycle_many(const ColumnBlock& r, ColumnBlock& z) {
  BlockSmoother& smoother = *block_smoother->smoother;
  z.resize(r.rows(), r.cols());
  smoother.smooth_many(r, z, true, true, available_threads());
  ColumnBlock residual;
  multiply_many(z, residual);
  residual = r - residual;
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> q(
      static_cast<Eigen::Index>(p_row_start.size()) - 1, coarse_csr.rows,
      static_cast<Eigen::Index>(p_value.size()), p_row_start.data(), p_column.data(),
      p_value.data());
  const Eigen::MatrixXd rc = q.transpose() * residual;
  Eigen::MatrixXd ec(rc.rows(), rc.cols());
  PC pc = nullptr;
  KSP coarse_ksp = nullptr;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCMGGetCoarseSolve(pc, &coarse_ksp), "PCMGGetCoarseSolve");
  const auto nc = static_cast<PetscInt>(rc.rows());
  for (Eigen::Index j = 0; j < rc.cols(); ++j) {
    Vec vb = nullptr, vx = nullptr;
    check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, nc, rc.col(j).data(), &vb),
          "VecCreateSeqWithArray");
    check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, nc, ec.col(j).data(), &vx),
          "VecCreateSeqWithArray");
    const PetscErrorCode code = KSPSolve(coarse_ksp, vb, vx);
    VecDestroy(&vb);
    VecDestroy(&vx);
    check(code, "KSPSolve (coarse)");
  }
  z.noalias() += q * ec;
  smoother.smooth_many(r, z, false, false, available_threads());
}

std::vector<KrylovOutcome> PetscKspSolver::solve_many(const Eigen::MatrixXd& rhs,
                                                      Eigen::MatrixXd& x) {
  Impl& m = *impl_;
  x.resize(rhs.rows(), rhs.cols());
  std::vector<KrylovOutcome> out;
  bool block = false;
  {
    const std::lock_guard lock(petsc_mutex());
    block = m.runs_block_vcycle();
  }
  if (!block) {
    for (Eigen::Index j = 0; j < rhs.cols(); ++j) {
      Eigen::VectorXd xj;
      out.push_back(solve(rhs.col(j), xj));
      x.col(j) = xj;
    }
    return out;
  }
  const std::lock_guard lock(petsc_mutex());
  ColumnBlock xb;
  const std::string name = "CG+pmg x" + std::to_string(rhs.cols());
  out = simultaneous_pcg([&](const ColumnBlock& in, ColumnBlock& y) { m.multiply_many(in, y); },
                         [&](const ColumnBlock& in, ColumnBlock& y) { m.vcycle_many(in, y); }, rhs,
                         xb, m.options.relative_tolerance, m.options.max_iterations,
                         m.options.progress, name.c_str());
  x = xb;
  return out;
}

// How the last KSPSolve ended.
KrylovOutcome PetscKspSolver::Impl::outcome(double b_norm) const {
  KrylovOutcome out;
  KSPConvergedReason reason;
  PetscInt iterations = 0;
  PetscReal rnorm = 0;
  KSPGetConvergedReason(ksp, &reason);
  KSPGetIterationNumber(ksp, &iterations);
  KSPGetResidualNorm(ksp, &rnorm);
  out.iterations = static_cast<int>(iterations);
  out.relative_residual = rnorm / b_norm;
  out.reason = KSPConvergedReasons[reason];
  KSPType type = nullptr;
  KSPGetType(ksp, &type);
  const bool preonly = type && std::string(type) == KSPPREONLY;
  // Only a stop on the tolerance is a solution (a direct solve through -ksp_type preonly
  // stops on its one iteration; the caller's residual check judges it).
  out.converged = reason == KSP_CONVERGED_RTOL || reason == KSP_CONVERGED_ATOL ||
                  reason == KSP_CONVERGED_RTOL_NORMAL || reason == KSP_CONVERGED_ATOL_NORMAL ||
                  reason == KSP_CONVERGED_HAPPY_BREAKDOWN ||
                  (preonly && reason == KSP_CONVERGED_ITS);
  return out;
}

void PetscKspSolver::begin_distributed(const Eigen::SparseMatrix<double>& lower_pattern) {
  const std::lock_guard lock(petsc_mutex());
  Impl& m = *impl_;
  m.release();
  m.distributed = true;
  PetscInt n = static_cast<PetscInt>(lower_pattern.rows()), local = PETSC_DECIDE, end = 0;
  // pmg: rows by a partition of the mesh (kept across Newton steps: the same pattern).
  if (m.options.preconditioner == "pmg" && m.options.prolongation) {
    if (m.options.rows) {
      m.partition_in_use = m.options.rows;
    } else {
      if (m.computed_partition.order.size() != static_cast<std::size_t>(n))
        m.computed_partition =
            partition_for_pmg(lower_pattern, *m.options.prolongation, m.options.smoother_block);
      m.partition_in_use = &m.computed_partition;
    }
    local = m.partition().own_end - m.partition().own_begin;
  } else {
    m.computed_partition = {};
    m.partition_in_use = &m.computed_partition;
    check(PetscSplitOwnership(PETSC_COMM_WORLD, &local, &n), "PetscSplitOwnership");
  }
  MPI_Scan(&local, &end, 1, MPIU_INT, MPI_SUM, PETSC_COMM_WORLD);
  const PetscInt begin = end - local;
  // Exact preallocation: per owned row, its columns inside the owned block (the "diagonal"
  // part) and outside it. Without it every MatSetValues that opens a new entry reallocates.
  std::vector<PetscInt> in_block(local, 0), off_block(local, 0);
  auto count = [&](PetscInt row, PetscInt col) {
    if (row >= begin && row < end)
      ++(col >= begin && col < end ? in_block : off_block)[row - begin];
  };
  for (PetscInt j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower_pattern, j); it; ++it) {
      const auto i = m.row_of(static_cast<PetscInt>(it.row())), jj = m.row_of(j);
      count(i, jj);
      if (i != jj)
        count(jj, i);
    }
  check(MatCreateAIJ(PETSC_COMM_WORLD, local, local, n, n, 0, in_block.data(), 0, off_block.data(),
                     &m.a),
        "MatCreateAIJ");
  check(VecCreateMPI(PETSC_COMM_WORLD, local, n, &m.rhs), "VecCreateMPI");
  check(VecSet(m.rhs, 0.0), "VecSet");
}

void PetscKspSolver::add_lower_share(const Eigen::SparseMatrix<double>& lower) {
  const std::lock_guard lock(petsc_mutex());
  Impl& m = *impl_;
  // Only the non-zero entries: a process's elements touch a small part of the pattern, and
  // every entry added in another process's rows travels to it at assembly.
  for (Eigen::Index j = 0; j < lower.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      if (it.value() == 0)
        continue;
      const auto row = m.row_of(static_cast<PetscInt>(it.row())),
                 col = m.row_of(static_cast<PetscInt>(j));
      check(MatSetValue(m.a, row, col, it.value(), ADD_VALUES), "MatSetValue");
      if (row != col)
        check(MatSetValue(m.a, col, row, it.value(), ADD_VALUES), "MatSetValue");
    }
}

// Own-row assembly: the matrix from each process's own rows only (own_row_matrix.hpp), rows
// as options.rows says (the partition computed before assembly).
void PetscKspSolver::assemble_own_rows(const Eigen::SparseMatrix<double>& lower) {
  const std::lock_guard lock(petsc_mutex());
  Impl& m = *impl_;
  if (!m.options.rows || m.options.rows->order.size() != static_cast<std::size_t>(lower.rows()))
    throw SolveError("internal: own-row assembly without the rows of this system");
  m.release();
  m.distributed = true;
  m.partition_in_use = m.options.rows;
  m.start_distributed_block_factor(&lower);
  m.block_factor_started = true;
  m.a = own_row_matrix(lower, m.partition());
  check(VecCreateMPI(PETSC_COMM_WORLD, m.partition().own_end - m.partition().own_begin,
                     static_cast<PetscInt>(lower.rows()), &m.rhs),
        "VecCreateMPI");
  check(VecSet(m.rhs, 0.0), "VecSet");
}

void PetscKspSolver::setup_distributed() {
  const std::lock_guard lock(petsc_mutex());
  Impl& m = *impl_;
  check(MatAssemblyBegin(m.a, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(m.a, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  if (!m.block_factor_started)
    m.start_distributed_block_factor(nullptr);
  m.block_factor_started = false;
  m.set_up_ksp(PETSC_COMM_WORLD);
}

KrylovOutcome PetscKspSolver::solve_distributed(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) {
  const std::lock_guard lock(petsc_mutex());
  Impl& m = *impl_;
  {
    PetscInt begin = 0, end = 0;
    check(VecGetOwnershipRange(m.rhs, &begin, &end), "VecGetOwnershipRange");
    PetscScalar* own = nullptr;
    check(VecGetArray(m.rhs, &own), "VecGetArray");
    for (PetscInt r = begin; r < end; ++r)
      own[r - begin] = rhs[m.equation_of(r)];
    check(VecRestoreArray(m.rhs, &own), "VecRestoreArray");
  }
  PetscReal b_norm = 0;
  check(VecNorm(m.rhs, NORM_2, &b_norm), "VecNorm");
  m.rhs_norm = b_norm;
  Vec vx = nullptr, r = nullptr, all = nullptr;
  VecScatter to_all = nullptr;
  auto destroy = [&] {
    VecDestroy(&vx);
    VecDestroy(&r);
    VecDestroy(&all);
    VecScatterDestroy(&to_all);
  };
  try {
    check(VecDuplicate(m.rhs, &vx), "VecDuplicate");
    check(VecSet(vx, 0.0), "VecSet");
    KrylovOutcome out;
    if (b_norm == 0) {
      out.converged = true;
      out.reason = "zero right-hand side";
      out.true_relative_residual = 0;
    } else {
      check(KSPSolve(m.ksp, m.rhs, vx), "KSPSolve");
      out = m.outcome(b_norm);
      // r = b - A x, by PETSc over the distributed matrix.
      check(VecDuplicate(m.rhs, &r), "VecDuplicate");
      check(MatMult(m.a, vx, r), "MatMult");
      check(VecAYPX(r, -1.0, m.rhs), "VecAYPX");
      PetscReal r_norm = 0;
      check(VecNorm(r, NORM_2, &r_norm), "VecNorm");
      out.true_relative_residual = r_norm / b_norm;
    }
    check(VecScatterCreateToAll(vx, &to_all, &all), "VecScatterCreateToAll");
    check(VecScatterBegin(to_all, vx, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
    check(VecScatterEnd(to_all, vx, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
    PetscInt n_all = 0;
    check(VecGetLocalSize(all, &n_all), "VecGetLocalSize");
    const PetscScalar* values = nullptr;
    check(VecGetArrayRead(all, &values), "VecGetArrayRead");
    x.resize(n_all); // the whole solution, back in equation order
    for (PetscInt i = 0; i < n_all; ++i)
      x[i] = values[m.row_of(i)];
    VecRestoreArrayRead(all, &values);
    destroy();
    return out;
  } catch (...) {
    destroy();
    throw;
  }
}

void PetscKspSolver::set_relative_tolerance(double tol) {
  const std::lock_guard lock(petsc_mutex());
  impl_->options.relative_tolerance = tol;
  if (impl_->ksp)
    check(KSPSetTolerances(impl_->ksp, tol, 0.0, PETSC_DEFAULT, impl_->options.max_iterations),
          "KSPSetTolerances");
}

int PetscKspSolver::block_factorizations() const {
  return impl_->block_factor.factorizations;
}

std::string PetscKspSolver::preconditioner_name() const {
  const std::lock_guard lock(petsc_mutex());
  if (!impl_->ksp)
    return impl_->options.preconditioner;
  PC pc = nullptr;
  KSPGetPC(impl_->ksp, &pc);
  PCType type = nullptr;
  PCGetType(pc, &type);
  if (!type)
    return impl_->options.preconditioner;
  if (std::string(type) == PCMG && impl_->options.preconditioner == "pmg")
    return "pmg";
  if (std::string(type) == PCHYPRE) {
    const char* hypre = nullptr;
    PCHYPREGetType(pc, &hypre);
    return hypre ? hypre : "hypre";
  }
  return type;
}

namespace {
// PETSc reads "-name value" pairs and quietly ignores a word that is neither, so that
// "pc_type gamg" would change nothing without a word. A name begins with '-' and a letter; a
// value (a number may be negative) follows a name, one per name.
std::string options_syntax_problem(const std::string& options) {
  std::istringstream words(options);
  std::string word;
  bool after_name = false;
  while (words >> word) {
    const bool name = word.size() > 1 && word[0] == '-' &&
                      (std::isalpha(static_cast<unsigned char>(word[1])) || word[1] == '_');
    if (!name && !after_name)
      return "'" + word +
             "' is neither a PETSc option (they begin with '-', e.g. -pc_type) nor the value "
             "of the option before it";
    after_name = name;
  }
  return "";
}
} // namespace

std::string petsc_options_problem(const PetscSolverOptions& options) {
  if (std::string why = options_syntax_problem(options.petsc_options); !why.empty())
    return why;
  // A 1D Laplacian with a fixed end (symmetric positive definite) and, for pmg, linear
  // interpolation from every other node.
  constexpr int n = 6;
  std::vector<Eigen::Triplet<double>> a, q;
  for (int i = 0; i < n; ++i) {
    a.emplace_back(i, i, 2.0);
    if (i + 1 < n)
      a.emplace_back(i + 1, i, -1.0);
    if (i % 2 == 0)
      q.emplace_back(i, i / 2, 1.0);
    else
      for (int c : {i / 2, i / 2 + 1})
        if (c < n / 2)
          q.emplace_back(i, c, 0.5);
  }
  Eigen::SparseMatrix<double> lower(n, n);
  lower.setFromTriplets(a.begin(), a.end());
  Eigen::SparseMatrix<double, Eigen::RowMajor> prolongation(n, n / 2);
  prolongation.setFromTriplets(q.begin(), q.end());
  PetscSolverOptions trial = options;
  trial.progress = nullptr;
  trial.prolongation = &prolongation;
  try {
    PetscKspSolver solver(trial);
    solver.setup(lower);
  } catch (const SolveError& e) {
    return e.what();
  }
  return "";
}

} // namespace magfem::petsc_module
