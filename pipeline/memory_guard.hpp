#pragma once
// The memory guard of a run. 3D: before the mesher allocates anything large, the estimated
// mesh (mesh/mesh_estimate3d.hpp) is turned into an estimated peak memory; a run that would
// need more than the limit stops with exit 2 and says which --mesh-scale would fit.
//
// Planar and axisymmetric: after meshing and before assembly (2D meshing takes a fraction of
// the solve and little memory), the triangles counted stand for the estimate; the same refusal.
//
// Peak memory model: a fixed base (libraries, the size field, the surface mesh) plus a cost
// per tetrahedron that depends on the element order (TetGen's own structures while meshing;
// the DOF map, the matrix and the linear solver's factor or preconditioner afterwards).
// per triangle in 2D (the matrix and CHOLMOD's factor). Calibrated on the examples
// (docs/performance.md, "Memory guard calibration": estimated against measured peak).
#include <functional>
#include <string>

#include "mesh/mesh_estimate3d.hpp"

namespace magfem {

// Estimated peak resident memory (MB) of a 3D solve with this many tetrahedra and coils
// (each coil's source field is memoised at the quadrature points, up to a fixed budget).
double estimated_peak_memory_mb(double tetrahedra, int order, int n_coils = 0);

// Estimated peak resident memory (MB) of a planar or axisymmetric solve on this many triangles.
double estimated_peak_memory_mb_2d(double triangles, int order);

// The memory a run may use, in MB: `max_memory_gb` if positive, else what the machine (and
// the cgroup the process runs in, if it has a limit) has available now.
double memory_limit_mb(double max_memory_gb);

// The limit one run is checked against. Runs that go on at once (the FE positions of a sweep
// with --jobs) share one limit: it is measured once for all of them (`shared_mb`, else at
// the check) and each may use 1/parallel_runs of it.
struct MemoryLimit {
  double max_memory_gb = 0; // --max-memory; 0: the memory available now
  double shared_mb = 0;     // the whole limit, fixed by the caller of parallel runs (MB)
  int parallel_runs = 1;
  double share_mb() const; // what this run may use, MB
};

// Throws InputError (field --max-memory when the limit came from it, else --mesh-scale;
// --jobs named when the limit is shared) when the estimate exceeds the limit, naming the
// --mesh-scale that would fit (searched with `tets_at_factor`, the estimate with every size
// multiplied by a factor), or saying that none up to 8 times the present one does;
// `mesh_scale` is the one in force (1 if none given).
void check_memory(const MeshEstimate3D& estimate, int order, int n_coils, const MemoryLimit& limit,
                  double mesh_scale, const std::function<double(double)>& tets_at_factor);
// The same for a planar or axisymmetric mesh of `triangles` (the --mesh-scale that would fit
// from the count's 1/scale^2 law).
void check_memory_2d(double triangles, int order, const MemoryLimit& limit, double mesh_scale);

} // namespace magfem
