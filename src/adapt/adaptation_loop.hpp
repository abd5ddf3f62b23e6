// The adaptation loop (docs/adaptation.md §Loop): passes of collapse, swap, split, swap and
// smoothing until the mesh is unit in its metric, then compaction. The library's P1 adaptation
// driver; `hocav adapt` curves its result with the curving driver.
#pragma once

#include <functional>
#include <vector>

#include "adapt/adaptation_metric.hpp"
#include "adapt/adaptation_operations.hpp"

namespace hocav {

// The default largest distance of a new boundary facet from the geometry, relative to the bounding box's
// diagonal (`hocav adapt --hausd`).
constexpr double kRelativeHausd = 0.01;

// Elements below this quality are poor (the report's "below 0.1" share).
constexpr double kPoorQuality = 0.1;

// A pass that splits and collapses fewer than this share of the vertices ends the loop, the P1 one
// and the curved one (0.1% ran one or two more passes for 0.02–0.34 points of unit share:
// docs/adaptation.md §The loop).
constexpr double kConvergedChange = 2.5e-3;

struct AdaptationSettings {
  int max_passes = 20;
  double feature_angle_degrees = 45;  // boundary sides meeting at more are ridges (2D: corners)
  double hausd = 0;                   // > 0: new boundary facets stay within this of the geometry
  int threads = 1;                    // the output does not depend on it
  // Stops this many passes after the loop's window closes (the distributed loop's early iterations,
  // whose frozen interfaces leave only ping-pong next to them: docs/distributed.md); negative: never.
  int passes_after_window_closes = -1;
  // Which edges at a required vertex a split may cut. A distributed part's required vertices are
  // mostly its frozen interface's, refined first (docs/distributed.md §Interfaces refined first):
  // splits toward an interface coarser than the metric would never end, and at its vertices on the
  // domain's boundary they left vertices off the geometry, and creases.
  SplitsAtRequiredVertices splits_at_required_vertices = SplitsAtRequiredVertices::kEvery;
  // False: the loop's classification takes its ridges from the mesh's tags and refs only, not from
  // its shape (kRidgesFromTagsOnly). A distributed part's loop: the whole mesh's shape was classified
  // once, as the serial loop classifies it, and a crease a part passes through on its way (a facet
  // far from the surface, mended later) must not become a feature line (docs/distributed.md).
  bool ridges_from_shape = true;
  // Not empty: per vertex of the input (compact), whether the first pass tries it; it also tries
  // the vertices of every element of quality below kPoorQuality, and later passes what changed, as
  // always. The distributed loop's last run near the interfaces its parts kept frozen, and around
  // the poor elements a part left (docs/distributed.md).
  std::vector<char> first_pass_vertices;
  // With first_pass_vertices: the first pass also tries the ends of every edge outside the unit
  // window [1/√2, √2] (what earlier runs left unfinished: the distributed loop's parts stop early).
  bool first_pass_unfinished_edges = false;
  // Called after each pass with its number (1-based) and the passes' cap, for progress.
  std::function<void(int, int)> progress;
  // False: the driver leaves the output unmeasured (the report's edge-length and quality figures
  // empty), for a run that prints and writes no report: the figures take a 16-point quadrature
  // per edge, 12% of the sphere shell's one-thread run (docs/usage.md).
  bool measure_output = true;
};

struct AdaptationPass {
  OperationCount collapses, splits, swaps, moves;
  Index vertices = 0, elements = 0;  // after the pass
  double seconds = 0;
  // Per operator (collapse, swap, split, smoothing) and for the compaction.
  double seconds_collapse = 0, seconds_swap = 0, seconds_split = 0, seconds_smooth = 0, seconds_compact = 0, seconds_settle = 0;
  // The boundary settling at the pass's start (with a geometry): vertices moved onto the geometry,
  // and part of the way (docs/adaptation.md §Boundary settling).
  Index settled = 0, partly_settled = 0;
  // The loop's window (docs/adaptation.md §The loop) during the pass: open, a collapse may make
  // edges up to collapse_length_bound (2); closed, up to √2.
  bool window_open = false;
  double collapse_length_bound = 0;
  // The split's coarse phase (3D: only edges longer than 2 were split): the pass cut coarse edges,
  // new work rather than ping-pong, so the window does not close after it.
  bool coarse_phase = false;
};

struct AdaptationRun {
  std::vector<AdaptationPass> passes;
  bool converged = false;  // stopped because a pass changed almost nothing, not at the cap
  // The window never closed: the loop stopped before a pass stalled (a window closed after the last
  // pass counts as closed).
  bool stopped_with_window_open = false;
  Index caps_removed = 0;  // after the last pass (remove_boundary_caps)
};

// Whether `pass` split and collapsed so few edges (fewer than 0.25% of its vertices) that the loop
// stops after it, unless the boundary's settling still got further in it (docs/adaptation.md §The
// loop, "Stopping").
bool changed_little(const AdaptationPass& pass);

// Adapts `mesh` (P1, with its topology) to `metric`; new boundary vertices go on `geometry` (none:
// on the straight boundary). The mesh is compact on return.
template <int D>
AdaptationRun adapt_to_metric(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                              const AdaptationSettings& settings);

}  // namespace hocav
