#include "studies/position_memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/input_error.hpp"
#include "pipeline/memory_guard.hpp"

namespace magfem {
namespace {

// The spread of the positions' meshes about the first one's (see the header).
constexpr double position_spread = 1.1;

} // namespace

void fit_jobs_to_memory(SweepJobs& jobs, double max_memory_gb, const MpiWorld& world,
                        int jobs_option) {
  // The processes of an mpirun on one machine share its memory as its positions do.
  jobs.memory_limit_mb = memory_limit_mb(max_memory_gb) / world.size_on_node;
  const double fit = std::floor(jobs.memory_limit_mb / (position_spread * jobs.position_memory_mb));
  jobs.used = static_cast<int>(std::clamp(fit, 1.0, static_cast<double>(jobs.requested)));
  if (jobs.used >= jobs.requested || !world.is_root())
    return;
  char what[96];
  if (jobs_option > 0)
    std::snprintf(what, sizeof what, "--jobs %d reduced to %d", jobs_option, jobs.used);
  else
    std::snprintf(what, sizeof what, "%d positions at once instead of %d (one per core)", jobs.used,
                  jobs.requested);
  std::fprintf(stderr,
               "magfem: note: %s: %d FE positions at once would need more than %s (%.2f GB; "
               "one needs about %.2f GB, estimated)\n",
               what, jobs.requested,
               max_memory_gb > 0 ? "the --max-memory limit" : "the memory available now",
               jobs.memory_limit_mb / 1024, jobs.position_memory_mb / 1024);
}

void share_memory(RunOverrides& overrides, const SweepJobs& jobs, const MpiWorld& world) {
  const int at_once = jobs.used * world.size_on_node;
  if (at_once > 1 && jobs.memory_limit_mb > 0)
    overrides.parallel_runs = at_once,
    overrides.shared_memory_mb = jobs.memory_limit_mb * world.size_on_node;
}

double check_position_memory_2d(CaseSpec first, const RunOverrides& overrides) {
  Mesh2D mesh;
  try {
    mesh = mesh_case_2d(first, overrides);
  } catch (const InputError&) {
    return 0; // a mesher error (a bad part): the position fails with it
  }
  const double triangles = static_cast<double>(mesh.n_triangles());
  check_memory_2d(triangles, first.order,
                  MemoryLimit{overrides.max_memory_gb, overrides.shared_memory_mb, 1},
                  overrides.mesh_scale > 0 ? overrides.mesh_scale : 1.0);
  return estimated_peak_memory_mb_2d(triangles, first.order);
}

int plan_positions_2d(const CaseSpec& first, RunOverrides& overrides, int workers,
                      const MpiWorld& world, int jobs_option, SweepJobs* jobs_used) {
  SweepJobs jobs;
  jobs.requested = jobs.used = workers;
  jobs.position_memory_mb = check_position_memory_2d(first, overrides);
  if (jobs.position_memory_mb > 0 && workers * world.size_on_node > 1)
    fit_jobs_to_memory(jobs, overrides.max_memory_gb, world, jobs_option);
  share_memory(overrides, jobs, world);
  if (jobs_used)
    *jobs_used = jobs;
  return jobs.used;
}

} // namespace magfem
