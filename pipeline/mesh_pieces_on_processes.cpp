#include "pipeline/mesh_pieces_on_processes.hpp"

#include <stdexcept>
#include <string>
#include <string_view>

#include "core/byte_records.hpp"
#include "mesh/mesh_error.hpp"

namespace magfem {
namespace {

// What a piece's owner sends: a tag byte, then the piece or the failure.
enum class Outcome : char { meshed = 'm', mesh_error = 'e', other_error = 'x' };

std::string other_error(int piece, int rank, const std::string& what) {
  std::string out(1, static_cast<char>(Outcome::other_error));
  append_record(out, "process " + std::to_string(rank) + ", meshing piece " +
                         std::to_string(piece) + " of the domain: " + what);
  return out;
}

std::string mesh_here(const MeshPiece3D& mesh, int piece, int rank) {
  try {
    return static_cast<char>(Outcome::meshed) + to_bytes(mesh(piece));
  } catch (const MeshError& e) {
    std::string out(1, static_cast<char>(Outcome::mesh_error));
    append_record(out, e.part);
    append_record(out, e.field);
    append_record(out, e.reason);
    return out;
  } catch (const std::exception& e) {
    return other_error(piece, rank, e.what());
  } catch (...) { // whatever it is, the other processes must hear of it, not wait for ever
    return other_error(piece, rank, "an exception that is not a std::exception");
  }
}

TetPieceMesh3D piece_or_throw(std::string_view bytes) {
  if (bytes.empty())
    throw std::runtime_error("a mesh piece arrived empty");
  const auto outcome = static_cast<Outcome>(bytes.front());
  bytes.remove_prefix(1);
  if (outcome == Outcome::meshed)
    return tet_piece_from_bytes(bytes);
  if (outcome == Outcome::mesh_error) {
    ByteRecordReader in(bytes, "a mesh piece's failure message");
    std::string part = in.text();
    std::string field = in.text();
    throw MeshError(std::move(part), std::move(field), in.text());
  }
  throw std::runtime_error(ByteRecordReader(bytes, "a mesh piece's failure message").text());
}

} // namespace

PieceRunner3D mesh_pieces_on_processes(const MpiWorld& world) {
  return [world](const MeshPiece3D& mesh) {
    std::array<std::string, 2> sent;
    const auto owner = [&](int piece) { return piece % world.size; };
    // Both pieces are meshed before either is sent: a process sends its piece when every
    // process has arrived at that piece's broadcast, i.e. has meshed its own.
    for (int p = 0; p < 2; ++p)
      if (world.rank == owner(p))
        sent[static_cast<std::size_t>(p)] = mesh_here(mesh, p, world.rank);
    for (int p = 0; p < 2; ++p)
      broadcast_bytes(owner(p), sent[static_cast<std::size_t>(p)]);
    std::array<TetPieceMesh3D, 2> pieces;
    for (std::size_t p = 0; p < 2; ++p)
      pieces[p] = piece_or_throw(sent[p]);
    return pieces;
  };
}

} // namespace magfem
