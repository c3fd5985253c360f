#include "solver/pmg_partition.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

#include <stdint.h> // scotch.h needs them first
#include <stdio.h>

#include <scotch/scotch.h>

#include "core/input_error.hpp"
#include "solver/on_root_for_all.hpp"
#include "solver/petsc_check.hpp"

namespace magfem::petsc_module {

namespace {

// The P1 graph of the vertices outside the shell (node[c] >= 0, numbered 0..n_nodes-1): two
// are adjacent where a tetrahedron joins them. CSR, each row sorted.
struct Graph {
  std::vector<PetscInt> start, adjacent;
};

Graph p1_graph(const Eigen::SparseMatrix<double>& lower_pattern,
               const std::vector<PetscInt>& vertex_coarse, const std::vector<PetscInt>& node,
               PetscInt n_nodes) {
  std::vector<std::vector<PetscInt>> neighbours(n_nodes);
  for (Eigen::Index j = 0; j < lower_pattern.outerSize(); ++j) {
    const PetscInt cj = vertex_coarse[j];
    if (cj < 0 || node[cj] < 0)
      continue;
    const PetscInt gj = node[cj];
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower_pattern, j); it; ++it) {
      const PetscInt ci = vertex_coarse[it.row()];
      if (ci < 0 || node[ci] < 0 || ci == cj)
        continue;
      const PetscInt gi = node[ci];
      neighbours[gi].push_back(gj);
      neighbours[gj].push_back(gi);
    }
  }
  Graph g;
  g.start.assign(1, 0);
  for (auto& row : neighbours) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    g.adjacent.insert(g.adjacent.end(), row.begin(), row.end());
    g.start.push_back(static_cast<PetscInt>(g.adjacent.size()));
    row = {};
  }
  return g;
}

// Each node's part (0 .. fraction.size()-1) by Scotch through PETSc's MatPartitioning on this
// process alone, the parts' sizes in the given fractions of the weights. The same graph gives
// the same parts in every run: Scotch on one thread (its threads' work sharing varies from run
// to run) from a fixed seed (Debian's Scotch seeds from the clock). SCOTCH_PTHREAD_NUMBER is
// read when Scotch starts its threads, per call.
std::vector<PetscInt> scotch_parts(const Graph& g, const std::vector<PetscInt>& weight,
                                   const std::vector<PetscReal>& fraction) {
  const auto n_nodes = static_cast<PetscInt>(g.start.size()) - 1;
  const auto size = static_cast<PetscInt>(fraction.size());
  // MatCreateMPIAdj and both weights take PetscMalloc'ed arrays and free them; until each is
  // handed over, `destroy` frees it (a null pointer is freed as nothing).
  PetscInt *ia = nullptr, *ja = nullptr, *w = nullptr;
  PetscReal* fractions = nullptr;
  Mat graph = nullptr;
  MatPartitioning partitioning = nullptr;
  IS part = nullptr;
  const auto destroy = [&] {
    ISDestroy(&part);
    MatPartitioningDestroy(&partitioning);
    MatDestroy(&graph);
    PetscFree(ia);
    PetscFree(ja);
    PetscFree(w);
    PetscFree(fractions);
  };
  std::vector<PetscInt> owner(n_nodes, 0);
  try {
    check(PetscMalloc1(n_nodes + 1, &ia), "PetscMalloc1");
    check(PetscMalloc1(std::max<std::size_t>(g.adjacent.size(), 1), &ja), "PetscMalloc1");
    check(PetscMalloc1(std::max<PetscInt>(n_nodes, 1), &w), "PetscMalloc1");
    check(PetscMalloc1(size, &fractions), "PetscMalloc1");
    std::copy(g.start.begin(), g.start.end(), ia);
    std::copy(g.adjacent.begin(), g.adjacent.end(), ja);
    for (PetscInt k = 0; k < n_nodes; ++k)
      w[k] = std::max<PetscInt>(weight[k], 1);
    std::copy(fraction.begin(), fraction.end(), fractions);
    check(MatCreateMPIAdj(PETSC_COMM_SELF, n_nodes, n_nodes, ia, ja, nullptr, &graph),
          "MatCreateMPIAdj");
    ia = ja = nullptr;
    check(MatPartitioningCreate(PETSC_COMM_SELF, &partitioning), "MatPartitioningCreate");
    check(MatPartitioningSetAdjacency(partitioning, graph), "MatPartitioningSetAdjacency");
    check(MatPartitioningSetType(partitioning, MATPARTITIONINGPTSCOTCH),
          "MatPartitioningSetType(ptscotch)");
    check(MatPartitioningSetNParts(partitioning, size), "MatPartitioningSetNParts");
    check(MatPartitioningSetVertexWeights(partitioning, w), "MatPartitioningSetVertexWeights");
    w = nullptr;
    check(MatPartitioningSetPartitionWeights(partitioning, fractions),
          "MatPartitioningSetPartitionWeights");
    fractions = nullptr;
    setenv("SCOTCH_PTHREAD_NUMBER", "1", 1);
    SCOTCH_randomSeed(1);
    SCOTCH_randomReset();
    check(MatPartitioningApply(partitioning, &part), "MatPartitioningApply");
    const PetscInt* parts = nullptr;
    check(ISGetIndices(part, &parts), "ISGetIndices");
    std::copy(parts, parts + n_nodes, owner.begin());
    check(ISRestoreIndices(part, &parts), "ISRestoreIndices");
  } catch (...) {
    destroy();
    throw;
  }
  destroy();
  return owner;
}

} // namespace

PmgPartition partition_for_pmg(const Eigen::SparseMatrix<double>& lower_pattern,
                               const Eigen::SparseMatrix<double, Eigen::RowMajor>& q,
                               const std::vector<int>* smoother_block) {
  const auto n = static_cast<PetscInt>(lower_pattern.rows());
  const auto m = static_cast<PetscInt>(q.cols());
  if (q.rows() != n || !q.isCompressed())
    throw SolveError("internal: the coarse space does not fit the system");
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const int* q_start = q.outerIndexPtr();
  const int* q_column = q.innerIndexPtr();
  // The P1 unknown of a vertex equation (its row of P is a single 1), and the P1 unknown an
  // equation goes with (a midpoint: its first free end; -1: none, both ends constrained).
  std::vector<PetscInt> vertex_coarse(n, -1), with(n, -1);
  for (PetscInt i = 0; i < n; ++i) {
    if (q_start[i + 1] == q_start[i])
      continue;
    with[i] = q_column[q_start[i]];
    if (q_start[i + 1] - q_start[i] == 1 && q.valuePtr()[q_start[i]] == 1.0)
      vertex_coarse[i] = with[i];
  }
  // The shell's equations, and every equation that goes with a shell vertex, to process 0.
  std::vector<char> in_shell(n, 0), shell_vertex(m, 0);
  if (smoother_block)
    for (int e : *smoother_block) {
      in_shell[e] = 1;
      if (vertex_coarse[e] >= 0)
        shell_vertex[vertex_coarse[e]] = 1;
    }
  // The graph: the P1 unknowns outside the shell, numbered in order.
  std::vector<PetscInt> node(m, -1), weight;
  PetscInt n_nodes = 0;
  for (PetscInt c = 0; c < m; ++c)
    if (!shell_vertex[c])
      node[c] = n_nodes++;
  weight.assign(n_nodes, 0);
  double n_to_zero = 0; // equations given to process 0 beforehand
  for (PetscInt i = 0; i < n; ++i) {
    if (with[i] >= 0 && (in_shell[i] || shell_vertex[with[i]]))
      in_shell[i] = 1;
    if (in_shell[i])
      n_to_zero += 1;
    else if (with[i] >= 0)
      ++weight[node[with[i]]];
  }
  // Fractions of the rest: each process n / size equations in all, process 0 its share less
  // what it has (at least a sliver, should the shell alone exceed a share).
  std::vector<PetscReal> fraction(size, 1.0);
  const double rest = std::max(1.0, static_cast<double>(n) - n_to_zero);
  if (size > 1) {
    fraction[0] = std::max(static_cast<double>(n) / size - n_to_zero, 0.02 * rest / size);
    for (int r = 1; r < size; ++r)
      fraction[r] = static_cast<double>(n) / size;
    const double sum = std::accumulate(fraction.begin(), fraction.end(), 0.0);
    for (auto& f : fraction)
      f /= sum;
  }
  // The whole graph partitioned by process 0 alone and its parts sent to the others: PT-Scotch
  // over the processes gave different parts from run to run (its parallel matching follows
  // the order messages arrive in; the magnetized sphere took 22 or 23 CG iterations and the
  // field moved in the last digits), and so did Scotch alone on each process, by its threads
  // and its clock-seeded random generator (scotch_parts).
  std::vector<PetscInt> coarse_part(m, 0);
  on_root_for_all(PETSC_COMM_WORLD, "the mesh's partition", [&] {
    const std::vector<PetscInt> owner =
        scotch_parts(p1_graph(lower_pattern, vertex_coarse, node, n_nodes), weight, fraction);
    for (PetscInt c = 0; c < m; ++c)
      if (node[c] >= 0)
        coarse_part[c] = owner[node[c]];
  });
  MPI_Bcast(coarse_part.data(), static_cast<int>(m), MPIU_INT, 0, PETSC_COMM_WORLD);
  // Rows: a process's equations after the previous processes'; an equation with no free
  // vertex (rare: a midpoint between two boundary vertices) by its place in the numbering.
  const auto number = [size](const std::vector<PetscInt>& part_of, std::vector<PetscInt>& out,
                             std::vector<PetscInt>& count) {
    count.assign(size + 1, 0);
    for (PetscInt p : part_of)
      ++count[p + 1];
    for (int r = 1; r <= size; ++r)
      count[r] += count[r - 1];
    std::vector<PetscInt> next(count.begin(), count.end() - 1);
    out.resize(part_of.size());
    for (std::size_t i = 0; i < part_of.size(); ++i)
      out[i] = next[part_of[i]]++;
  };
  std::vector<PetscInt> part_of(n), start;
  for (PetscInt i = 0; i < n; ++i)
    part_of[i] = in_shell[i]    ? 0
                 : with[i] >= 0 ? coarse_part[with[i]]
                                : static_cast<PetscInt>((static_cast<long long>(i) * size) / n);
  PmgPartition out;
  number(part_of, out.order, start);
  out.own_begin = start[rank];
  out.own_end = start[rank + 1];
  out.local_equations.resize(out.own_end - out.own_begin);
  for (PetscInt i = 0; i < n; ++i)
    if (part_of[i] == rank)
      out.local_equations[out.order[i] - out.own_begin] = i;
  number(coarse_part, out.coarse_order, start);
  out.coarse_local = start[rank + 1] - start[rank];
  return out;
}

} // namespace magfem::petsc_module
