#pragma once
// Under mpirun, who meshes the two pieces of a domain split for TetGen (mesh/domain_split3d.hpp):
// process 0 the inner piece, process 1 the outer one (process 0 both when it is alone), each
// then sent to every process, which stitches them into the mesh a serial run makes.
//
// Why: each process of a distributed solve has one thread and needs the whole mesh (replicated
// meshing, then each keeps its share of the elements). Meshing the whole domain on every
// process took benchmark32 11.7 s under mpirun -n 2 against 7.1 s for a serial run's two
// threads; one piece per process takes the larger piece's time.
//
// A piece that fails (a TetGen error, out of memory) fails on every process with the same
// message: a MeshError stays a MeshError (naming its part and field), anything else becomes a
// std::runtime_error naming the process.
#include "mesh/tet_piece_mesh3d.hpp"
#include "solver/mpi_context.hpp"

namespace magfem {

PieceRunner3D mesh_pieces_on_processes(const MpiWorld& world);

} // namespace magfem
