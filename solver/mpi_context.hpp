#pragma once
// The processes of one run when magfem is launched by mpirun: which one this is, how many
// there are, and the few collective operations the distributed 3D solve and the studies
// dealt across processes need outside the linear algebra (agreeing that replicated data is
// identical, dealing work items and collecting their results, stopping every process on an
// error). MPI itself stays in the PETSc module (petsc_backend.hpp); nothing else includes it.
//
// A process not launched by mpirun never starts MPI here (a serial run pays nothing).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace magfem {

class WorkDealerEngine;

struct MpiWorld {
  int rank = 0;         // this process in MPI_COMM_WORLD
  int size = 1;         // processes in MPI_COMM_WORLD; 1 = a serial run
  int size_on_node = 1; // of them on this machine (they share its memory)
  // MPI_THREAD_MULTIPLE granted: any thread may call MPI (join_mpi_world(true)).
  bool any_thread_calls_mpi = false;
  bool distributed() const { return size > 1; }
  bool is_root() const { return rank == 0; }
};

// True when the environment says this process was started by mpirun (Open MPI's
// OMPI_COMM_WORLD_SIZE, MPICH/Hydra's PMI_SIZE), whatever the number of processes.
bool launched_by_mpirun();

// Under mpirun: starts MPI (through PETSc, which the distributed solve needs anyway) and
// returns this process's place in MPI_COMM_WORLD. Otherwise {0, 1, 1}, and MPI stays off.
// `any_thread_calls_mpi` asks for MPI_THREAD_MULTIPLE (whether it was granted is in the
// result); only the first call of a process chooses.
MpiWorld join_mpi_world(bool any_thread_calls_mpi = false);

// Threads a process may use by default: the cores of its machine shared evenly among the
// processes of the run on it (at least one). A serial run: every core.
int threads_per_process(const MpiWorld& world);

// This process's place in MPI_COMM_WORLD if MPI has been started (and not yet stopped),
// else {0, 1, 1}; never starts it. For error paths, which must not start MPI.
MpiWorld started_mpi_world();

// Collective: whether every process passed the same value (e.g. a hash of a replicated mesh).
bool same_on_every_rank(std::uint64_t value);

// Collective: `values` (n, the same length everywhere) summed over the processes, the same bits
// on every process (rank 0 sums and sends the sum back, where an all-reduce may round
// differently from process to process): replicated vectors of a distributed solve, whose
// every process must take the same Newton decisions. No-op in a serial run.
void sum_on_every_rank(double* values, std::size_t n);
// Collective: `values` combined over the processes into rank 0's by a bitwise OR of their bits
// (the others' are unchanged). For tables each process fills its own entries of (the rest
// +0.0f, all bits clear) and rank 0 alone reads whole: exact where one process alone computed
// an entry and where several computed the same bits (own-row assembly's ghost tetrahedra,
// which a sum would count twice). No-op in a serial run.
void union_to_root(float* values, std::size_t n);

// Collective: waits until every process has arrived, sleeping between checks. Open MPI's
// blocking calls spin on the CPU; processes waiting here for rank 0's post-processing leave
// it the cores instead.
void idle_barrier();

// Collective: rank 0 may run its threads on every core that the run's processes on its machine
// are bound to (the union of their CPU affinities), for the post-processing it does alone
// while the others wait in idle_barrier, sleeping. mpirun binds each of two processes to one
// core by default, so rank 0's post-processing threads would otherwise share its one core.
// The others' affinities stay; no-op in a serial run.
void lend_node_cores_to_root();

// Collective: rank 0's `code` on every process (the exit code of a run whose outcome rank 0
// decides), waiting as idle_barrier does.
int code_of_root(int code);

// Collective: process `root`'s `bytes` on every process (waiting as idle_barrier does: the
// others may wait seconds for it). No-op in a serial run.
void broadcast_bytes(int root, std::string& bytes);

// Work items (here: the indices of a sweep's positions) dealt to the processes of
// MPI_COMM_WORLD one at a time as each asks, so that a process takes the next item when it
// finishes one (positions differ in cost, processes in speed), and each finished item's
// result (text) sent back to rank 0 with the next request.
//
// Why rank 0 hands out the indices rather than an MPI one-sided counter (MPI_Fetch_and_op
// on a window at rank 0): with Open MPI over TCP (no hardware atomics, no asynchronous
// progress) the atomic completes only when rank 0 next enters MPI, which it does not while it
// solves a position, and the results need a receiver at rank 0 anyway. So rank 0's main thread
// only serves (serve(): requests and results, polled with short sleeps, so it leaves the
// cores to the solves) while its worker threads take items from the same counter (next()).
// Several threads of one process may call next() only when any_thread_calls_mpi.
class WorkDealer {
public:
  // Collective. `items`: the list to deal, at rank 0 (ignored elsewhere); `workers`: the
  // threads of this process that will call next() (numbered 0 .. workers - 1).
  WorkDealer(std::vector<int> items, int workers);
  ~WorkDealer();
  WorkDealer(const WorkDealer&) = delete;
  WorkDealer& operator=(const WorkDealer&) = delete;

  // The next item for `worker` of this process, or -1 when none is left. At rank 0 from the
  // shared counter (results stay with the caller). Elsewhere asked of rank 0, sending with the
  // request the item this worker finished last (`finished`, -1: none) and its `result`.
  int next(int worker, int finished = -1, const std::string& result = "");

  // Rank 0, main thread: answers the other processes' requests, calling on_result(item,
  // result) for each result as it arrives, until every worker of theirs has been told that
  // none is left (so every result is in). Returns at once on the other processes.
  void serve(const std::function<void(int item, const std::string& result)>& on_result);

private:
  std::unique_ptr<WorkDealerEngine> engine_; // in the PETSc module
};

// Ends every process of the run with `code` (MPI_Abort): an error on one process must not
// leave the others waiting in a collective call for ever.
[[noreturn]] void abort_mpi_world(int code);

} // namespace magfem
