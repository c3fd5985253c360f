#include "solver/mpi_world_backend.hpp"

#include <mpi.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "solver/petsc_ksp_solver.hpp"

namespace magfem::petsc_module {

MpiWorld started_mpi_world() {
  MpiWorld world;
  int started = 0, finalized = 0;
  MPI_Initialized(&started);
  MPI_Finalized(&finalized);
  if (!started || finalized)
    return world;
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  return world;
}

MpiWorld join_mpi_world(bool any_thread_calls_mpi) {
  MpiWorld world;
  // MPI_Init, and PETSc's error handling, once for the process
  start_petsc(any_thread_calls_mpi);
  int provided = MPI_THREAD_SINGLE;
  MPI_Query_thread(&provided);
  world.any_thread_calls_mpi = provided >= MPI_THREAD_MULTIPLE;
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, world.rank, MPI_INFO_NULL, &node);
  if (node != MPI_COMM_NULL) {
    MPI_Comm_size(node, &world.size_on_node);
    MPI_Comm_free(&node);
  }
  return world;
}

bool same_on_every_rank(std::uint64_t value) {
  if (!started_mpi_world().distributed())
    return true;
  std::uint64_t low = value, high = value;
  MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
  return low == high;
}

namespace {

// MPI counts are ints: long arrays travel in pieces.
constexpr std::size_t max_piece = std::size_t{1} << 28;

template <class T>
void reduce_to_root(T* values, std::size_t n, MPI_Datatype type, int rank, MPI_Op op = MPI_SUM) {
  for (std::size_t at = 0; at < n; at += max_piece) {
    const int count = static_cast<int>(std::min(max_piece, n - at));
    MPI_Reduce(rank == 0 ? MPI_IN_PLACE : values + at, values + at, count, type, op, 0,
               MPI_COMM_WORLD);
  }
}

} // namespace

void sum_on_every_rank(double* values, std::size_t n) {
  const MpiWorld world = started_mpi_world();
  if (!world.distributed())
    return;
  reduce_to_root(values, n, MPI_DOUBLE, world.rank);
  for (std::size_t at = 0; at < n; at += max_piece)
    MPI_Bcast(values + at, static_cast<int>(std::min(max_piece, n - at)), MPI_DOUBLE, 0,
              MPI_COMM_WORLD);
}

void union_to_root(float* values, std::size_t n) {
  static_assert(sizeof(float) == sizeof(std::uint32_t));
  const MpiWorld world = started_mpi_world();
  if (world.distributed())
    reduce_to_root(reinterpret_cast<std::uint32_t*>(values), n, MPI_UINT32_T, world.rank, MPI_BOR);
}

namespace {

// Waits for a non-blocking operation, sleeping between checks: Open MPI's blocking calls spin
// on the CPU, which would take it from the solves of this process or of another one on the
// same core.
void wait_idly(MPI_Request& request, std::chrono::milliseconds pause) {
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done)
      return;
    std::this_thread::sleep_for(pause);
  }
}

} // namespace

void idle_barrier() {
  if (!started_mpi_world().distributed())
    return;
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  wait_idly(request, std::chrono::milliseconds(20));
}

cpu_set_t node_cores() {
  cpu_set_t mine, all;
  CPU_ZERO(&mine);
  if (sched_getaffinity(0, sizeof mine, &mine) != 0)
    CPU_ZERO(&mine); // unknown: adds nothing
  all = mine;
  if (!started_mpi_world().distributed())
    return all;
  // cpu_set_t is a bit mask in unsigned longs: OR-ed over the processes of the machine.
  constexpr int n_words = sizeof(cpu_set_t) / sizeof(unsigned long);
  static_assert(sizeof(cpu_set_t) % sizeof(unsigned long) == 0);
  unsigned long in[n_words], out[n_words];
  std::memcpy(in, &mine, sizeof mine);
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  MPI_Allreduce(in, out, n_words, MPI_UNSIGNED_LONG, MPI_BOR, node);
  MPI_Comm_free(&node);
  std::memcpy(&all, out, sizeof all);
  return all;
}

void lend_node_cores_to_root() {
  const MpiWorld world = started_mpi_world();
  if (!world.distributed())
    return;
  const cpu_set_t all = node_cores();
  cpu_set_t mine;
  CPU_ZERO(&mine);
  if (!world.is_root() || sched_getaffinity(0, sizeof mine, &mine) != 0)
    return;
  // Threads started from now on (magfem's loops start theirs per loop) inherit the mask.
  if (CPU_COUNT(&all) > CPU_COUNT(&mine))
    sched_setaffinity(0, sizeof all, &all);
}

int code_of_root(int code) {
  if (!started_mpi_world().distributed())
    return code;
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Ibcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD, &request);
  wait_idly(request, std::chrono::milliseconds(20));
  return code;
}

void broadcast_bytes(int root, std::string& bytes) {
  if (!started_mpi_world().distributed())
    return;
  // Waits of seconds (a process still meshing its piece): a 5 ms sleep costs nothing.
  constexpr std::chrono::milliseconds pause(5);
  std::uint64_t n = bytes.size();
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Ibcast(&n, 1, MPI_UINT64_T, root, MPI_COMM_WORLD, &request);
  wait_idly(request, pause);
  bytes.resize(n);
  for (std::size_t at = 0; at < n; at += max_piece) {
    MPI_Ibcast(bytes.data() + at, static_cast<int>(std::min<std::size_t>(max_piece, n - at)),
               MPI_CHAR, root, MPI_COMM_WORLD, &request);
    wait_idly(request, pause);
  }
}

// Messages of the dealer, on its own communicator: a request (to rank 0) is the worker's
// number, the item it finished (-1: none) and that item's result text; the reply (tagged for
// the worker, so that replies cannot cross between the threads of a process) is an item or -1.
namespace {
constexpr int request_tag = 1;
constexpr int reply_tag = 2; // + the worker's number
// Polling interval: requests come once per position (seconds apart); 2 ms costs nothing.
constexpr std::chrono::milliseconds dealer_pause(2);
} // namespace

struct MpiWorkDealer::Impl {
  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  std::vector<int> items;
  std::atomic<std::size_t> taken{0};
  int remote_workers = 0; // workers of the other processes (rank 0)

  int take() {
    const std::size_t k = taken++;
    return k < items.size() ? items[k] : -1;
  }
  int ask_root(int worker, int finished, const std::string& result);
  void answer(const MPI_Status& status,
              const std::function<void(int, const std::string&)>& on_result, int& stops);
};

MpiWorkDealer::MpiWorkDealer(std::vector<int> items, int workers)
    : impl_(std::make_unique<Impl>()) {
  MPI_Comm_dup(MPI_COMM_WORLD, &impl_->comm);
  MPI_Comm_rank(impl_->comm, &impl_->rank);
  if (impl_->rank == 0)
    impl_->items = std::move(items);
  int remote = impl_->rank == 0 ? 0 : workers;
  MPI_Reduce(impl_->rank == 0 ? MPI_IN_PLACE : &remote, &remote, 1, MPI_INT, MPI_SUM, 0,
             impl_->comm);
  impl_->remote_workers = remote;
}

MpiWorkDealer::~MpiWorkDealer() {
  if (impl_->comm != MPI_COMM_NULL)
    MPI_Comm_free(&impl_->comm);
}

int MpiWorkDealer::Impl::ask_root(int worker, int finished, const std::string& result) {
  std::string message(2 * sizeof(int), '\0');
  std::memcpy(message.data(), &worker, sizeof(int));
  std::memcpy(message.data() + sizeof(int), &finished, sizeof(int));
  message += result;
  int item = -1;
  MPI_Request requests[2];
  MPI_Irecv(&item, 1, MPI_INT, 0, reply_tag + worker, comm, &requests[1]);
  MPI_Isend(message.data(), static_cast<int>(message.size()), MPI_BYTE, 0, request_tag, comm,
            &requests[0]);
  wait_idly(requests[0], dealer_pause);
  wait_idly(requests[1], dealer_pause);
  return item;
}

int MpiWorkDealer::next(int worker, int finished, const std::string& result) {
  if (impl_->rank == 0)
    return impl_->take();
  return impl_->ask_root(worker, finished, result);
}

void MpiWorkDealer::Impl::answer(const MPI_Status& status,
                                 const std::function<void(int, const std::string&)>& on_result,
                                 int& stops) {
  int bytes = 0;
  MPI_Get_count(&status, MPI_BYTE, &bytes);
  std::string message(static_cast<std::size_t>(bytes), '\0');
  MPI_Recv(message.data(), bytes, MPI_BYTE, status.MPI_SOURCE, request_tag, comm,
           MPI_STATUS_IGNORE);
  if (message.size() < 2 * sizeof(int))
    throw std::runtime_error("work dealer: a request of " + std::to_string(bytes) + " bytes");
  int worker = 0, finished = -1;
  std::memcpy(&worker, message.data(), sizeof(int));
  std::memcpy(&finished, message.data() + sizeof(int), sizeof(int));
  if (finished >= 0)
    on_result(finished, message.substr(2 * sizeof(int)));
  int item = take();
  stops += item < 0;
  MPI_Send(&item, 1, MPI_INT, status.MPI_SOURCE, reply_tag + worker, comm);
}

void MpiWorkDealer::serve(
    const std::function<void(int item, const std::string& result)>& on_result) {
  if (impl_->rank != 0)
    return;
  for (int stops = 0; stops < impl_->remote_workers;) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, request_tag, impl_->comm, &arrived, &status);
    if (arrived)
      impl_->answer(status, on_result, stops);
    else
      std::this_thread::sleep_for(dealer_pause);
  }
}

void abort_mpi_world(int code) {
  if (started_mpi_world().distributed())
    MPI_Abort(MPI_COMM_WORLD, code);
}

} // namespace magfem::petsc_module
