#pragma once
// The memory guard of a sweep's FE positions (pipeline/memory_guard.hpp), for every dimension.
// A position that alone needs more than the limit is bad input for the whole sweep (exit 2
// before any position, naming the --mesh-scale that fits, as for solve). Positions that run at
// once each need their own memory: rather than refuse a sweep whose positions fit one at a
// time but not W at once, fewer run at once, as many as fit, each checked against a 1/W share
// of the limit (the first position's estimate stands for all; the others' meshes differ by a
// few per cent, hence a 10 % margin).
#include "casefile/case_spec.hpp"
#include "pipeline/run2d.hpp"
#include "solver/mpi_context.hpp"

namespace magfem {

// How many positions ran at once.
struct SweepJobs {
  int requested = 1;             // --jobs, or one per core; at most one per position
  int used = 1;                  // fewer when the memory holds fewer FE positions at once
  double position_memory_mb = 0; // estimated peak of one FE position (0: not estimated)
  double memory_limit_mb = 0;    // the limit they share (0: not estimated)
};

// With jobs.position_memory_mb set (one position's estimate): jobs.memory_limit_mb (the limit
// of --max-memory, else the memory available now, split among the processes of an mpirun on
// this machine) and jobs.used, as many of jobs.requested as fit; a note on stderr (rank 0)
// when fewer run than asked for (`jobs_option`: --jobs, 0 when not given).
void fit_jobs_to_memory(SweepJobs& jobs, double max_memory_gb, const MpiWorld& world,
                        int jobs_option);

// The overrides every position solves with: each checked against its share of the limit
// the positions running at once on this machine (under mpirun also those of the other
// processes on it) share.
void share_memory(RunOverrides& overrides, const SweepJobs& jobs, const MpiWorld& world);

// Planar and axisymmetric: the first position's case meshed (cheap in 2D) and checked alone
// against the whole limit (InputError naming --max-memory or --mesh-scale); returns its
// estimated peak (MB). A position the mesher rejects returns 0: it fails as a position, with
// its message.
double check_position_memory_2d(CaseSpec first, const RunOverrides& overrides);

// A 2D sweep's positions fitted to the memory (the two steps above): `workers` requested,
// the overrides given their share; returns the workers that run.
int plan_positions_2d(const CaseSpec& first, RunOverrides& overrides, int workers,
                      const MpiWorld& world, int jobs_option, SweepJobs* jobs_used = nullptr);

} // namespace magfem
