#pragma once
// Adaptive refinement of a 3D case, as spec.adapt asks (the loop, its marking and stopping
// rules: adapt_loop.hpp):
//   solve -> estimate the error per tetrahedron (error_estimate3d.hpp) -> stop, or size
//   sources from the indicators -> a new TetGen mesh of the case with them -> repeat.
//
// Why a new mesh rather than TetGen's refinement of the old one (tetgen -r with a metric):
// the mesher builds the surfaces again from the geometry, so nodes of curved faces lie on
// them at every pass (refining the old mesh would put new boundary nodes on the flat facets
// of the first mesh and freeze its geometric error), and regions, material ids, the open
// boundary's shell, chord and gap rules and the memory guard hold by construction. The
// adaptive sizes enter the mesher's own size field as sources, combined with the case's
// sizes by the minimum: the case's mesh is the coarsest the loop makes.
#include <functional>
#include <memory>
#include <vector>

#include "pipeline/adapt_loop.hpp"
#include "pipeline/run3d.hpp"

namespace magfem {

// The last pass's run, with run->adapt filled in. on_pass (may be empty) hears every pass as
// it ends. Throws as run_case_3d does; not under mpirun (one process solves every pass).
std::unique_ptr<Run3D> run_adaptive_3d(const CaseSpec& spec, const RunOverrides& overrides,
                                       const std::function<void(const AdaptPass&)>& on_pass = {});

// The size sources of the next pass: at every node and tet centroid of run's mesh, the
// size the tet was asked to have (Mesh3D::tet_size) times adapt_size_ratios (a node takes the
// smallest of its tets'), the open boundary's shell by its own indicator like every other
// tet. Exposed for the tests.
std::vector<SizeSample3D> adapted_size_samples_3d(const Run3D& run, double target_pct,
                                                  bool coarsen);

} // namespace magfem
