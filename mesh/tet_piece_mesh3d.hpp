#pragma once
// One piece of a split domain's volume mesh (domain_split3d.hpp) as TetGen returned it, its
// byte form, and who meshes the two pieces.
//
// Who meshes them is the caller's choice: in one process, two threads (or one after the other);
// under mpirun, one process each, the pieces then sent to every process
// (pipeline/mesh_pieces_on_processes.hpp). Each piece's mesh depends on the piece alone (its
// own random generator, the whole domain's predicate filters: tetgen_shared_state.hpp), so
// every choice stitches the same mesh.
#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace magfem {

struct TetPieceMesh3D {
  std::vector<double> points;     // x, y, z per point: the piece's surface points first
  std::vector<int> tets;          // 4 point indices per tetrahedron
  std::vector<double> attributes; // TetGen's region attribute per tetrahedron

  bool operator==(const TetPieceMesh3D&) const = default;
};

// The piece as bytes (sizes, then the arrays as they are in memory: for processes of one
// build) and back. tet_piece_from_bytes throws std::runtime_error on a truncated string.
std::string to_bytes(const TetPieceMesh3D& piece);
TetPieceMesh3D tet_piece_from_bytes(std::string_view bytes);

// Meshes piece 0 (inside the cut) or 1 (outside).
using MeshPiece3D = std::function<TetPieceMesh3D(int piece)>;
// Returns both pieces, having called mesh_piece for each piece somewhere (here or in another
// process); an exception from either reaches the caller.
using PieceRunner3D = std::function<std::array<TetPieceMesh3D, 2>(const MeshPiece3D& mesh_piece)>;

} // namespace magfem
