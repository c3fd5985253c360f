#include "mesh/tet_piece_mesh3d.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace magfem {
namespace {

template <class T> void append(std::string& out, const std::vector<T>& values) {
  const std::uint64_t n = values.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  out.append(reinterpret_cast<const char*>(values.data()), n * sizeof(T));
}

template <class T> void take(std::string_view& in, std::vector<T>& values) {
  std::uint64_t n = 0;
  if (in.size() < sizeof n)
    throw std::runtime_error("a mesh piece's bytes end early");
  std::memcpy(&n, in.data(), sizeof n);
  in.remove_prefix(sizeof n);
  if (in.size() / sizeof(T) < n)
    throw std::runtime_error("a mesh piece's bytes end early");
  values.resize(n);
  std::memcpy(values.data(), in.data(), n * sizeof(T));
  in.remove_prefix(n * sizeof(T));
}

} // namespace

std::string to_bytes(const TetPieceMesh3D& piece) {
  std::string out;
  out.reserve(3 * sizeof(std::uint64_t) + piece.points.size() * sizeof(double) +
              piece.tets.size() * sizeof(int) + piece.attributes.size() * sizeof(double));
  append(out, piece.points);
  append(out, piece.tets);
  append(out, piece.attributes);
  return out;
}

TetPieceMesh3D tet_piece_from_bytes(std::string_view bytes) {
  TetPieceMesh3D piece;
  take(bytes, piece.points);
  take(bytes, piece.tets);
  take(bytes, piece.attributes);
  if (!bytes.empty())
    throw std::runtime_error("a mesh piece's bytes run on past its arrays");
  return piece;
}

} // namespace magfem
