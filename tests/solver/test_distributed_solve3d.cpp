// The element shares of a distributed solve: every tetrahedron assembled by exactly one
// process, in contiguous ranges whose sizes differ by at most one. (The distributed solve
// itself runs under mpirun in tests/cli/test_mpi.cpp.)
#include <gtest/gtest.h>

#include <algorithm>

#include "solver/distributed_solve3d.hpp"

namespace {

TEST(ElementShare, EveryElementOnceInBalancedContiguousRanges) {
  for (std::size_t n : {0, 1, 5, 7, 64, 78302})
    for (int size : {1, 2, 3, 8}) {
      std::size_t next = 0, smallest = n, largest = 0;
      for (int rank = 0; rank < size; ++rank) {
        const magfem::ElementRange r = magfem::element_share(n, rank, size);
        EXPECT_EQ(r.first, next) << n << " elements, rank " << rank << " of " << size;
        EXPECT_LE(r.first, r.last);
        next = r.last;
        smallest = std::min(smallest, r.last - r.first);
        largest = std::max(largest, r.last - r.first);
      }
      EXPECT_EQ(next, n) << n << " elements over " << size;
      EXPECT_LE(largest - smallest, 1u) << n << " elements over " << size;
    }
}

} // namespace
