#pragma once
// TetGen 1.5's process-wide state, made safe for two tetrahedralize() calls at once (the two
// pieces of a split mesh, mesh/domain_split3d.hpp). What the library shares between calls:
//
// 1. The exact predicates' error bounds and static filters (predicates.cxx globals), set by
//    exactinit() at the start of every call from that call's bounding box. A filter sized for a
//    smaller box lets a wrong sign through. libtet calls exactinit through its PLT (one call
//    site, objdump), so the definition in tetgen_shared_state.cpp takes its place: while a
//    TetGenSharedFilters is alive, exactinit does nothing and the filters stay those of the box
//    it was given (the whole domain's: a filter for a larger box is only more cautious, never
//    wrong).
// 2. glibc's rand(), which TetGen seeds with srand() and draws from to shuffle its insertion
//    order (incrementaldelaunay, insertconstrainedpoints, collectremovepoints). Two calls
//    drawing from the one generator interleave, so each call's order, and mesh, would depend on
//    the threads' timing. While a TetGenPieceScope is alive on a thread, rand and srand use a
//    generator of that thread's own (glibc's random_r, so the sequence is glibc's rand's).
// 3. tetgenmesh's static index tables (inittables()), rewritten at every call with the same
//    constant values: harmless.
//
// Everything else of a call lives in its tetgenmesh, tetgenio and tetgenbehavior. The caller
// still holds the one TetGen lock (mesher3d.cpp) for the whole two-piece meshing, so no third
// call sees the pinned filters.

namespace magfem {

// Sets TetGen's predicate filters for a box of extents dx, dy, dz (metres) and keeps them while
// alive (exactinit calls in between are ignored). Only one may be alive at a time.
class TetGenSharedFilters {
public:
  TetGenSharedFilters(double dx, double dy, double dz);
  ~TetGenSharedFilters();
  TetGenSharedFilters(const TetGenSharedFilters&) = delete;
  TetGenSharedFilters& operator=(const TetGenSharedFilters&) = delete;

  // exactinit calls ignored so far in this process (TetGen's own, one per call while pinned):
  // that they reach this file at all shows the interposition in place.
  static long ignored_calls();

  // Whether a call of exactinit made as libtet makes it reaches the definition here (so the
  // filters stay pinned). Not in every process: in a module that Python opens RTLD_LOCAL the
  // lookup may find another definition first.
  bool pinned_for_tetgen() const;

private:
  double dx_, dy_, dz_;
};

// rand() and srand() on the calling thread use a generator of the thread's own, seeded as
// glibc's is at start-up (1), for the life of this object.
class TetGenPieceScope {
public:
  TetGenPieceScope();
  ~TetGenPieceScope();
  TetGenPieceScope(const TetGenPieceScope&) = delete;
  TetGenPieceScope& operator=(const TetGenPieceScope&) = delete;

  // Whether rand() called as libtet calls it reaches the per-thread generator here. In the
  // Python module glibc's rand, in the global scope, is found first: there two pieces meshed
  // at once would share glibc's generator, and their meshes would depend on the timing.
  static bool reaches_tetgen();
};

// Whether two pieces may be meshed at once in this process: both interpositions in effect
// (`filters`: the ones the caller holds). Otherwise the pieces are meshed one after the other,
// which gives the same mesh (each TetGen call seeds its generator and sets its filters itself).
bool tetgen_calls_may_overlap(const TetGenSharedFilters& filters);

} // namespace magfem
