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
#include <string>
#include <vector>

#include "pipeline/adapt_loop.hpp"
#include "pipeline/run3d.hpp"

namespace magfem {

// The last pass's run, with run->adapt filled in. on_pass (may be empty) hears every pass as
// it ends. Throws as run_case_3d does; not under mpirun (one process solves every pass).
std::unique_ptr<Run3D> run_adaptive_3d(const CaseSpec& spec, const RunOverrides& overrides,
                                       const std::function<void(const AdaptPass&)>& on_pass = {});

// A probe table named in adapt.quantities, as the marking and the estimate see it on one
// mesh. Goal-oriented: the change of the table's rms |B| between passes says nothing about
// its pointwise field (benchmark32's r56 "converged" at a 0.3 % change while 2.3-4 % off the
// charge model pointwise), and the energy's indicators put the unknowns at the energy's hot
// spots (magnet edges), not at the probe. The field error at a probe point is mostly the
// local error of the tets around it (postproc/probe_error3d.hpp), plus pollution from the
// energy error elsewhere, which the energy rule keeps reducing.
struct ProbeGoal3D {
  std::string name;
  std::vector<std::size_t> point_tets; // the tet holding each point (physical tets)
  std::vector<Vec3> points;            // where each lies in the model, parallel (metres)
  std::vector<double> point_error_T;   // e_K of each point's tet, parallel (T)
  std::vector<std::size_t> zone;       // those and their neighbours (probe_zone_rings)
  std::vector<double> zone_error_T;    // e_K of each zone tet, parallel to zone (T)
  double rms_B_T = 0;                  // rms |B| over the table (the quantity's value)
  // 100 rms over the points of their tet's e_K / rms_B_T: the estimated rms pointwise
  // error of the table (%), reported as the quantity's one-mesh estimate (AdaptMeasure).
  double error_pct = 0;
};

// Vertex-sharing rings around a probe's tets that take the probe's size rule. One ring is
// 11 % of the tets of benchmark32 at --mesh-scale 3 (r56, 2116 points). Not measured apart:
// two rings with the 0.3 clamp and the energy rule beside it reached r56 at 0.51-0.56 %
// pointwise with 2.57M unknowns in two passes; one ring, 0.5 and the rule below, 0.36-0.43 %
// with 1.90M in three.
inline constexpr int probe_zone_rings = 1;
// The smallest ratio h_new / h a probe point's source asks for in one pass: up to 20x finer,
// 8000x the tets around the point. The sphere's r = 12 mm table from its coarse start asked
// for 0.11 at most; a smaller request is capped, and the next pass takes the rest.
inline constexpr double min_point_ratio = 0.05;

// The goals of the probe quantities among `quantities` (others are skipped), in order.
std::vector<ProbeGoal3D> probe_goals_3d(const Run3D& run,
                                        const std::vector<AdaptQuantity>& quantities);

// The size sources of the next pass: at every node and tet centroid of run's mesh, the
// size the tet was asked to have (Mesh3D::tet_size) times adapt_size_ratios (a node takes the
// smallest of its tets'), the open boundary's shell by its own indicator like every other
// tet. Tets in a goal's zone take the smaller of that and the probe rule
//   h_new = h * clamp((e_target / e_K)^(1/p), 0.5, 2),  e_target = probe_target_pct / 100 rms|B|,
// (e_K: postproc/probe_error3d.hpp; the field error of a tet falls like h^p). 0.5, not the
// energy rule's 0.3: a probe's zone is often clamped whole, and 0.3 allows 37x its tets in
// one pass (benchmark32, with two rings: 380k -> 2.57M unknowns, the table at 0.54 % where
// the aim was 0.25 %).
// Each probe point is a source too, sized by the same rule in one jump (clamped to
// [min_point_ratio, 1] only): h_K (e_target / e_K)^(1/p). The zone's tets are the old mesh's,
// and on a coarse mesh one ring of them is a thick shell: refining it whole spent the
// unknowns there, while sources at the points themselves put the small sizes where the table
// reads the field and the mesher grades them away (0.3 per unit length). Magnetized sphere,
// r = 12 mm table (703 points) to 0.1 % from the 22k-unknown start: the zone rule alone took 4
// passes to 1.33M unknowns (0.078 % estimated, 0.058-0.067 % true); with the point sources 2
// passes to 816k (0.075 %, 0.052-0.054 %). Exposed for the tests.
std::vector<SizeSample3D> adapted_size_samples_3d(const Run3D& run, double target_pct, bool coarsen,
                                                  const std::vector<ProbeGoal3D>& goals = {},
                                                  double probe_target_pct = 0);

} // namespace magfem
