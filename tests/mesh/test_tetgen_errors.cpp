// TetGen's failures come back as exceptions and the process goes on
// (mesh/tetgen_termination.cpp). Measured without it, on these inputs: two crossing
// tetrahedron surfaces (a self-intersecting PLC, TetGen's code 3) died by SIGSEGV, its memory
// pools freed twice while the error unwound; two crossing triangles failed TetGen's assertion
// in fillregion and aborted. Each input runs three times: nothing was left half freed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include <tetgen.h>

#include "mesh/tetgen_termination.hpp"

namespace magfem {
extern const int tetgen_termination_interposed;
}

namespace {

// A PLC of triangles; TetGen's switches "pQ" (tetrahedralize the PLC, quiet).
void tetrahedralize_triangles(const std::vector<double>& points,
                              const std::vector<std::array<int, 3>>& triangles) {
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size() / 3);
  in.pointlist = new REAL[points.size()];
  std::copy(points.begin(), points.end(), in.pointlist);
  in.numberoffacets = static_cast<int>(triangles.size());
  in.facetlist = new tetgenio::facet[triangles.size()];
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3]{triangles[t][0], triangles[t][1], triangles[t][2]};
  }
  tetgenbehavior b;
  char switches[] = "pQ";
  ASSERT_TRUE(b.parse_commandline(switches));
  const magfem::TetGenErrorScope scope;
  tetrahedralize(&b, &in, &out);
}

TEST(TetGenErrors, ASelfIntersectingSurfaceThrowsCode3) {
  ASSERT_EQ(magfem::tetgen_termination_interposed, 1);
  const std::vector<double> points = {0,   0,   0,   1,   0,   0,   0,   1,   0,   0,   0,   1,
                                      0.3, 0.3, 0.3, 1.3, 0.3, 0.3, 0.3, 1.3, 0.3, 0.3, 0.3, 1.3};
  const std::vector<std::array<int, 3>> tris = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3},
                                                {4, 5, 6}, {4, 5, 7}, {4, 6, 7}, {5, 6, 7}};
  for (int round = 0; round < 3; ++round) {
    int code = 0;
    try {
      tetrahedralize_triangles(points, tris);
    } catch (int c) {
      code = c;
    }
    EXPECT_EQ(code, 3) << "TetGen's self-intersection code";
  }
}

TEST(TetGenErrors, AFailedAssertionInsideTetGenThrows) {
  const std::vector<double> points = {0,   0,   0,    1,   0,   0,   0,   1,   0,
                                      0.2, 0.2, -0.5, 0.2, 0.2, 0.5, 0.9, 0.9, 0};
  for (int round = 0; round < 3; ++round)
    EXPECT_THROW(tetrahedralize_triangles(points, {{0, 1, 2}, {3, 4, 5}}), magfem::TetGenAssertion);
}

} // namespace
