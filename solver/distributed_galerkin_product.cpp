#include "solver/distributed_galerkin_product.hpp"

#include <algorithm>
#include <vector>

#include "core/input_error.hpp"
#include "solver/galerkin_product.hpp"
#include "solver/petsc_check.hpp"
#include "solver/sparse_row_accumulator.hpp"

namespace magfem::petsc_module {

namespace {

// A sequential AIJ matrix's CSR arrays, read in place.
struct SeqCsr {
  const PetscInt* row_start = nullptr;
  const PetscInt* column = nullptr;
  PetscScalar* value = nullptr;
};

SeqCsr csr_of(Mat m) {
  SeqCsr c;
  PetscMemType memory = PETSC_MEMTYPE_HOST;
  check(MatSeqAIJGetCSRAndMemType(m, &c.row_start, &c.column, &c.value, &memory),
        "MatSeqAIJGetCSRAndMemType");
  if (memory != PETSC_MEMTYPE_HOST)
    throw SolveError("internal: the fine matrix is not in host memory");
  return c;
}

// This process's share of P^T A P, its rows numbered by coarse_order (ascending in P1 order,
// not in coarse_order).
struct Share {
  CsrMatrix rows;
  std::vector<int> coarse; // the coarse row of each row of `rows`
};

Share share_of_own_rows(Mat a, const Eigen::SparseMatrix<double, Eigen::RowMajor>& q,
                        const PmgPartition& rows) {
  PetscInt begin = 0, end = 0;
  check(MatGetOwnershipRange(a, &begin, &end), "MatGetOwnershipRange");
  Mat diag = a, off = nullptr;
  const PetscInt* off_rows = nullptr; // the global row of each off-diagonal column
  PetscBool is_mpi = PETSC_FALSE;
  check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(a), MATMPIAIJ, &is_mpi),
        "PetscObjectTypeCompare");
  if (is_mpi)
    check(MatMPIAIJGetSeqAIJ(a, &diag, &off, &off_rows), "MatMPIAIJGetSeqAIJ");
  // The diagonal block's columns are the process's own rows, so one map serves both.
  const int* own_equation = rows.local_equations.data();
  const SeqCsr d = csr_of(diag);
  std::vector<CsrRowBlock> blocks = {{d.row_start, d.column, d.value, own_equation}};
  std::vector<int> off_equation;
  if (off) {
    PetscInt n_off = 0;
    check(MatGetSize(off, nullptr, &n_off), "MatGetSize");
    std::vector<int> equation_of_row(rows.order.size());
    for (std::size_t e = 0; e < rows.order.size(); ++e)
      equation_of_row[static_cast<std::size_t>(rows.order[e])] = static_cast<int>(e);
    off_equation.resize(static_cast<std::size_t>(n_off));
    for (PetscInt k = 0; k < n_off; ++k)
      off_equation[static_cast<std::size_t>(k)] = equation_of_row[off_rows[k]];
    const SeqCsr o = csr_of(off);
    blocks.push_back({o.row_start, o.column, o.value, off_equation.data()});
  }
  Share s;
  s.rows =
      partial_galerkin_product(static_cast<int>(end - begin), blocks, own_equation, q, s.coarse);
  for (int& c : s.coarse)
    c = rows.coarse_order[static_cast<std::size_t>(c)];
  for (int& c : s.rows.column)
    c = rows.coarse_order[static_cast<std::size_t>(c)];
  return s;
}

// What one process sends another: per row its coarse row and length, then its columns; the
// values apart.
struct Message {
  std::vector<int> index;
  std::vector<double> value;
};

std::vector<Message> messages_by_owner(const Share& s, const std::vector<int>& coarse_end) {
  std::vector<Message> out(coarse_end.size());
  const CsrMatrix& r = s.rows;
  for (int i = 0; i < r.rows; ++i) {
    const auto owner = static_cast<std::size_t>(
        std::upper_bound(coarse_end.begin(), coarse_end.end(), s.coarse[i]) - coarse_end.begin());
    Message& m = out[owner];
    m.index.push_back(s.coarse[i]);
    m.index.push_back(r.row_start[i + 1] - r.row_start[i]);
    m.index.insert(m.index.end(), r.column.begin() + r.row_start[i],
                   r.column.begin() + r.row_start[i + 1]);
    m.value.insert(m.value.end(), r.value.begin() + r.row_start[i],
                   r.value.begin() + r.row_start[i + 1]);
  }
  return out;
}

// All-to-all of `data` (one vector per process) into one vector, the processes' parts in rank
// order.
template <class T>
std::vector<T> exchange(const std::vector<std::vector<T>>& data, MPI_Datatype type) {
  const int size = static_cast<int>(data.size());
  std::vector<int> send_count(size), receive_count(size), send_at(size + 1, 0),
      receive_at(size + 1, 0);
  for (int p = 0; p < size; ++p)
    send_count[p] = static_cast<int>(data[p].size());
  MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, PETSC_COMM_WORLD);
  std::vector<T> send;
  for (int p = 0; p < size; ++p) {
    send.insert(send.end(), data[p].begin(), data[p].end());
    send_at[p + 1] = send_at[p] + send_count[p];
    receive_at[p + 1] = receive_at[p] + receive_count[p];
  }
  std::vector<T> received(static_cast<std::size_t>(receive_at[size]));
  MPI_Alltoallv(send.data(), send_count.data(), send_at.data(), type, received.data(),
                receive_count.data(), receive_at.data(), type, PETSC_COMM_WORLD);
  return received;
}

// The rows [coarse_begin, coarse_end) from the received shares: each entry added in the order
// received (process by process), columns sorted.
CsrMatrix sum_received(const std::vector<int>& index, const std::vector<double>& value,
                       PetscInt coarse_begin, PetscInt coarse_end, int m) {
  const auto n_rows = static_cast<std::size_t>(coarse_end - coarse_begin);
  // Pass 1: each row's entries, duplicates counted; pass 2: them in arrival order.
  std::vector<int> start(n_rows + 1, 0);
  for (std::size_t k = 0; k < index.size(); k += 2 + static_cast<std::size_t>(index[k + 1]))
    start[static_cast<std::size_t>(index[k] - coarse_begin) + 1] += index[k + 1];
  for (std::size_t i = 0; i < n_rows; ++i)
    start[i + 1] += start[i];
  std::vector<int> next(start.begin(), start.end() - 1), column(start.back());
  std::vector<double> entry(start.back());
  for (std::size_t k = 0, v = 0; k < index.size();
       k += 2 + static_cast<std::size_t>(index[k + 1])) {
    int& at = next[static_cast<std::size_t>(index[k] - coarse_begin)];
    for (int e = 0; e < index[k + 1]; ++e, ++at, ++v) {
      column[static_cast<std::size_t>(at)] = index[k + 2 + static_cast<std::size_t>(e)];
      entry[static_cast<std::size_t>(at)] = value[v];
    }
  }
  CsrMatrix c;
  c.rows = static_cast<int>(n_rows);
  c.cols = m;
  c.row_start.push_back(0);
  SparseRowAccumulator acc(m);
  for (std::size_t i = 0; i < n_rows; ++i) {
    acc.begin_row();
    for (int k = start[i]; k < start[i + 1]; ++k)
      acc.add(column[static_cast<std::size_t>(k)], entry[static_cast<std::size_t>(k)]);
    acc.append_row(c.column, c.value);
    c.row_start.push_back(static_cast<int>(c.column.size()));
  }
  return c;
}

} // namespace

Mat distributed_galerkin_product(Mat a, const Eigen::SparseMatrix<double, Eigen::RowMajor>& q,
                                 const PmgPartition& rows, PetscInt coarse_begin,
                                 PetscInt coarse_end) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  std::vector<int> ends(static_cast<std::size_t>(size));
  const int own_end = static_cast<int>(coarse_end);
  MPI_Allgather(&own_end, 1, MPI_INT, ends.data(), 1, MPI_INT, PETSC_COMM_WORLD);
  const int m = static_cast<int>(q.cols());
  CsrMatrix mine;
  {
    std::vector<std::vector<int>> index(static_cast<std::size_t>(size));
    std::vector<std::vector<double>> value(static_cast<std::size_t>(size));
    {
      std::vector<Message> messages = messages_by_owner(share_of_own_rows(a, q, rows), ends);
      for (int p = 0; p < size; ++p) {
        index[p] = std::move(messages[p].index);
        value[p] = std::move(messages[p].value);
      }
    }
    const std::vector<int> received_index = exchange(index, MPI_INT);
    const std::vector<double> received_value = exchange(value, MPI_DOUBLE);
    mine = sum_received(received_index, received_value, coarse_begin, coarse_end, m);
  }
  Mat coarse = nullptr;
  check(MatCreateMPIAIJWithArrays(PETSC_COMM_WORLD, coarse_end - coarse_begin,
                                  coarse_end - coarse_begin, m, m, mine.row_start.data(),
                                  mine.column.data(), mine.value.data(), &coarse),
        "MatCreateMPIAIJWithArrays (coarse operator)");
  return coarse;
}

} // namespace magfem::petsc_module
