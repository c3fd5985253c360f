#pragma once
// A contiguous range of a mesh's elements: the share of the element loops one process of a
// distributed solve runs (distributed_solve3d.hpp).
#include <cstddef>
#include <limits>

namespace magfem {

// The elements [first, last) of the mesh's order; last is clamped to the element count, so the
// default is every element.
struct ElementRange {
  std::size_t first = 0, last = std::numeric_limits<std::size_t>::max();
  bool whole(std::size_t n_elements) const { return first == 0 && last >= n_elements; }
};

// The tetrahedra [first, last) process `rank` of `size` assembles: contiguous ranges of the
// mesh's element order with sizes that differ by at most one. The element loop is the work
// being shared and its cost per element is nearly uniform (one order, one quadrature rule
// apart from shell and curved elements), so equal counts balance it, and a range needs no
// partitioner. The price is locality: rows are owned in contiguous equation blocks, which
// need not match an element range, and the entries of rows another process owns travel to
// it once, at assembly (a graph partition of the elements would cut that traffic).
ElementRange element_share(std::size_t n_elements, int rank, int size);

} // namespace magfem
