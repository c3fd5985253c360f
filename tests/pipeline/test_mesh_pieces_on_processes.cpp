// Under mpirun the two pieces of a split domain are meshed one per process and sent to every
// process (pipeline/mesh_pieces_on_processes.hpp). This test runs itself under mpirun with a
// stand-in for TetGen that records which pieces each process meshed: each piece exactly once
// (process 0 the inner, 1 the outer, a third none), every process receiving both unchanged, and
// a failure of one piece reaching every process with the same error (a MeshError still naming
// its part and field). The real meshes: test_mpi_solve's split-mesh test (serial field kept).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "mesh/mesh_error.hpp"
#include "pipeline/mesh_pieces_on_processes.hpp"
#include "tests/cli/mpi_helpers.hpp"

namespace fs = std::filesystem;

namespace magfem {
namespace {

// A piece whose every number says which piece it is (1000 points: more than one small message).
TetPieceMesh3D stand_in_piece(int piece) {
  TetPieceMesh3D m;
  for (int i = 0; i < 3000; ++i)
    m.points.push_back(piece + 1e-3 * i);
  for (int i = 0; i < 400; ++i)
    m.tets.push_back(7 * piece + i);
  m.attributes.assign(100, piece + 0.5);
  return m;
}

// The child: what one process of an mpirun meshed and received, written to rank.<r> in the
// folder MAGFEM_PIECES_CHILD names; MAGFEM_PIECES_FAIL = mesh | other | int makes piece 1 fail.
TEST(PiecesOnProcessesChild, WritesWhatThisProcessMeshedAndReceived) {
  const char* out = std::getenv("MAGFEM_PIECES_CHILD");
  if (!out)
    GTEST_SKIP() << "run by the tests below under mpirun";
  const std::string fail =
      std::getenv("MAGFEM_PIECES_FAIL") ? std::getenv("MAGFEM_PIECES_FAIL") : "";
  const MpiWorld world = join_mpi_world();
  std::string meshed;
  const MeshPiece3D mesh = [&](int p) {
    meshed += std::to_string(p);
    if (p == 1 && fail == "mesh")
      throw MeshError("magnet", "max_size", "TetGen could not refine it");
    if (p == 1 && fail == "other")
      throw std::runtime_error("out of memory");
    if (p == 1 && fail == "int")
      throw 42;
    return stand_in_piece(p);
  };
  std::string outcome;
  try {
    const auto pieces = mesh_pieces_on_processes(world)(mesh);
    outcome = pieces[0] == stand_in_piece(0) && pieces[1] == stand_in_piece(1) ? "received both"
                                                                               : "received wrong";
  } catch (const MeshError& e) {
    outcome = "mesh error " + e.part + " | " + e.field + " | " + e.reason;
  } catch (const std::exception& e) {
    outcome = std::string("error ") + e.what();
  }
  std::ofstream(fs::path(out) / ("rank." + std::to_string(world.rank)))
      << "meshed " << meshed << "\n"
      << outcome << "\n";
}

class PiecesOnProcesses : public ::testing::Test {
protected:
  void SetUp() override {
    if (const std::string why = test::why_no_mpi_children("MAGFEM_PIECES_CHILD"); !why.empty())
      GTEST_SKIP() << why;
  }

  // Each process's report of `mpirun -n <n>` of the child.
  std::vector<std::string> run(int n, const std::string& fail = "") {
    const fs::path dir = test::fresh_dir("pieces_" + std::to_string(n) + fail);
    const test::CliOutcome o = test::run_mpi_children(
        n, "PiecesOnProcessesChild.*", "MAGFEM_PIECES_CHILD", dir, {{"MAGFEM_PIECES_FAIL", fail}});
    EXPECT_EQ(o.status, 0) << o.out;
    std::vector<std::string> reports;
    for (int r = 0; r < n; ++r)
      reports.push_back(test::text_of(dir / ("rank." + std::to_string(r))));
    fs::remove_all(dir);
    return reports;
  }
};

TEST_F(PiecesOnProcesses, TwoProcessesMeshOnePieceEachAndBothReceiveBoth) {
  const auto reports = run(2);
  EXPECT_EQ(reports[0], "meshed 0\nreceived both\n");
  EXPECT_EQ(reports[1], "meshed 1\nreceived both\n");
}

TEST_F(PiecesOnProcesses, AThirdProcessMeshesNothingAndReceivesBoth) {
  const auto reports = run(3);
  EXPECT_EQ(reports[0], "meshed 0\nreceived both\n");
  EXPECT_EQ(reports[1], "meshed 1\nreceived both\n");
  EXPECT_EQ(reports[2], "meshed \nreceived both\n");
}

// The error stays what it was: the case reader maps a MeshError's part and field to the case
// file's line, on every process alike (a process that went on alone would hang the others).
TEST_F(PiecesOnProcesses, APieceThatFailsFailsEveryProcessWithItsError) {
  const auto mesh = run(2, "mesh");
  EXPECT_EQ(mesh[0], "meshed 0\nmesh error magnet | max_size | TetGen could not refine it\n");
  EXPECT_EQ(mesh[1], "meshed 1\nmesh error magnet | max_size | TetGen could not refine it\n");
  const auto other = run(2, "other");
  const std::string said = "error process 1, meshing piece 1 of the domain: out of memory\n";
  EXPECT_EQ(other[0], "meshed 0\n" + said);
  EXPECT_EQ(other[1], "meshed 1\n" + said);
  // Not a std::exception at all: still said on every process rather than left to hang them.
  const auto odd = run(2, "int");
  const std::string odd_said =
      "error process 1, meshing piece 1 of the domain: an exception that is not a "
      "std::exception\n";
  EXPECT_EQ(odd[0], "meshed 0\n" + odd_said);
  EXPECT_EQ(odd[1], "meshed 1\n" + odd_said);
}

TEST(TetPieceBytes, RoundTripAndTruncation) {
  const TetPieceMesh3D piece = stand_in_piece(1);
  const std::string bytes = to_bytes(piece);
  EXPECT_EQ(tet_piece_from_bytes(bytes), piece);
  EXPECT_THROW(tet_piece_from_bytes(std::string_view(bytes).substr(0, bytes.size() - 1)),
               std::runtime_error);
  EXPECT_THROW(tet_piece_from_bytes(bytes + "x"), std::runtime_error);
  EXPECT_EQ(tet_piece_from_bytes(to_bytes(TetPieceMesh3D{})), TetPieceMesh3D{});
}

} // namespace
} // namespace magfem
