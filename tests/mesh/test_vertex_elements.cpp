// VertexElements (mesh/vertex_elements.hpp): the patches of both recoveries start from it. On
// a fan of triangles and a pair of tetrahedra, each vertex lists exactly the elements that
// have it as a corner, in increasing order, and a vertex of no element lists none (an off-by-one
// in the counts' prefix sum shifts every list; a fill that reuses `first` overwrites them).
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "mesh/vertex_elements.hpp"

namespace magfem {
namespace {

std::vector<int> listed(const auto& around, int vertex) {
  const auto span = around.of(vertex);
  return {span.begin(), span.end()};
}

TEST(VertexElements, EachVertexListsTheTrianglesAroundIt) {
  // A fan of three triangles around vertex 0; vertex 5 belongs to none.
  const std::vector<std::array<int, 3>> triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  const VertexElements<3> around(triangles, 6);
  EXPECT_EQ(listed(around, 0), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(listed(around, 1), (std::vector<int>{0}));
  EXPECT_EQ(listed(around, 2), (std::vector<int>{0, 1}));
  EXPECT_EQ(listed(around, 3), (std::vector<int>{1, 2}));
  EXPECT_EQ(listed(around, 4), (std::vector<int>{2}));
  EXPECT_TRUE(listed(around, 5).empty());
}

TEST(VertexElements, EachVertexListsTheTetrahedraAroundIt) {
  const std::vector<std::array<int, 4>> tets = {{0, 1, 2, 3}, {1, 2, 3, 4}};
  const VertexElements<4> around(tets, 5);
  EXPECT_EQ(listed(around, 0), (std::vector<int>{0}));
  for (int shared : {1, 2, 3})
    EXPECT_EQ(listed(around, shared), (std::vector<int>{0, 1}));
  EXPECT_EQ(listed(around, 4), (std::vector<int>{1}));
}

} // namespace
} // namespace magfem
