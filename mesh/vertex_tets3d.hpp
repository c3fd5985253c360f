#pragma once
// The tets around each vertex of a 3D mesh (mesh/vertex_elements.hpp).
#include "mesh/mesh3d.hpp"
#include "mesh/vertex_elements.hpp"

namespace magfem {

class VertexTets3D : public VertexElements<4> {
public:
  explicit VertexTets3D(const Mesh3D& mesh) : VertexElements<4>(mesh.tets, mesh.n_nodes()) {}
};

} // namespace magfem
