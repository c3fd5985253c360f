#include "mesh/tet_piece_mesh3d.hpp"

#include <cstdint>
#include <stdexcept>

#include "core/byte_records.hpp"

namespace magfem {

std::string to_bytes(const TetPieceMesh3D& piece) {
  std::string out;
  out.reserve(3 * sizeof(std::uint64_t) + piece.points.size() * sizeof(double) +
              piece.tets.size() * sizeof(int) + piece.attributes.size() * sizeof(double));
  append_record(out, piece.points);
  append_record(out, piece.tets);
  append_record(out, piece.attributes);
  return out;
}

TetPieceMesh3D tet_piece_from_bytes(std::string_view bytes) {
  ByteRecordReader in(bytes, "a mesh piece's bytes");
  TetPieceMesh3D piece;
  piece.points = in.array<double>();
  piece.tets = in.array<int>();
  piece.attributes = in.array<double>();
  if (!in.done())
    throw std::runtime_error("a mesh piece's bytes run on past its arrays");
  return piece;
}

} // namespace magfem
