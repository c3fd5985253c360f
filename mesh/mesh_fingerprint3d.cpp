#include "mesh/mesh_fingerprint3d.hpp"

#include <cstring>

namespace magfem {
namespace {

// FNV-1a over raw bytes: order-dependent, so a renumbering changes it too (the element
// shares would then differ even for the same geometry).
class Fnv1a {
public:
  template <class T> void add(const std::vector<T>& items) {
    add_bytes(items.size());
    const auto* bytes = reinterpret_cast<const unsigned char*>(items.data());
    for (std::size_t i = 0; i < items.size() * sizeof(T); ++i)
      mix(bytes[i]);
  }
  std::uint64_t value() const { return hash_; }

private:
  void add_bytes(std::size_t n) {
    unsigned char b[sizeof n];
    std::memcpy(b, &n, sizeof n);
    for (unsigned char c : b)
      mix(c);
  }
  void mix(unsigned char c) {
    hash_ ^= c;
    hash_ *= 0x100000001b3ULL;
  }
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

} // namespace

std::uint64_t mesh_fingerprint(const Mesh3D& mesh) {
  Fnv1a h;
  h.add(mesh.nodes); // Eigen::Vector3d: three packed doubles
  h.add(mesh.tets);
  h.add(mesh.tet_part);
  h.add(mesh.outer_faces);
  return h.value();
}

} // namespace magfem
