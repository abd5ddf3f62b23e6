// The curved passes of a distributed `adapt --curved`, in its parts (docs/distributed.md §Curved
// passes in the parts): no process gathers the curved mesh. Every part runs the passes
// (adapt_curved) with its interfaces frozen; then the elements near each interface go, P2 nodes and
// all, to one of its two processes (cut_last_run_region), whose passes run again with that
// interface inside the part; last, the elements near the seams of those regions (where three or
// more parts met) go to rank 0, whose passes run once more.
#pragma once

#include <array>
#include <vector>

#include "adapt/curved_adaptation.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// The curved passes asked of a distributed run: none when max_passes is 0.
struct CurvedPassesSettings {
  int max_passes = 0;
  double feature_angle_degrees = 45;  // classifies the boundary's vertices, as the P1 loop's --angle
};

// One round of the passes, the same on every process.
struct CurvedPassRound {
  Index elements = 0;        // in the round's parts (after the migration that made them)
  Index moved_elements = 0;  // that the migration before the round moved to another process
  long long bytes_sent = 0;  // by that migration and its vertices' log-metrics
  int passes = 0;            // the most any part ran
  double seconds = 0;        // the slowest process's, migration included
};

// What the passes did, the same on every process.
struct CurvedPassesInParts {
  // The rounds' passes one after the other, each pass the parts' passes of that number: counts and
  // sizes summed over the parts, times the slowest part's.
  CurvedAdaptationRun run;
  std::array<CurvedPassRound, 3> rounds{};  // every part; the interfaces' regions; the seams on rank 0
};

// Every process at once, each with its curved part (P2, compact, with topology, global ids and
// pinned flags) and the log-metric of each of its vertices, `log_metrics`: the passes' three rounds,
// each in the field of its parts' vertices' log-metrics (the first round's the part as given),
// the new vertices numbered after every process's largest global id. On return `log_metrics` holds
// those of the part's vertices, sampled in the last round's field.
template <int D>
CurvedPassesInParts adapt_curved_in_parts(MeshPart<D>& part, std::vector<SymMat<D>>& log_metrics, const BoundaryGeometry<D>* geometry,
                                          const P2CavityOptions& options, const CurvedPassesSettings& settings, int threads);

}  // namespace hocav
