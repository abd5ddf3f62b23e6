// The curved passes of `hocav adapt --curved` (docs/adaptation.md §Curved passes): on the curved
// output of the P1 loop and the reinsertion, P2 collapses of the edges shorter than 1/√2 and P2
// splits of those longer than √2, both judged by the curved edge's Riemannian length, then P2 swaps
// and vertex moves that raise the worst curved mean ratio of their cavity, until a pass changes
// almost nothing. Every operation is a P2 cavity operation (cavity/p2_operations.hpp), so
// the mesh stays P2 and certified above the Jacobian floor after each one. The operations are
// serial (the scans that list candidates run on threads): the output does not depend on the thread
// count. With a geometry, boundary edges are split and flipped (3D) and boundary vertices collapsed
// too, their new vertices and boundary nodes on the geometry (curved_boundary.hpp); the moves are
// of inner vertices.
#pragma once

#include <span>

#include <vector>

#include "cavity/p2_cavity_operator.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

struct CurvedOperationCount {
  Index done = 0;
  Index boundary_done = 0;  // of those done, on the boundary (a boundary edge split or flipped, a boundary vertex removed)
  // Refused: an edge or removed vertex on the boundary where no boundary operation applies (a feature
  // line, a corner, no geometry), or whose new facets would turn or fold (CurvedBoundary).
  Index on_boundary = 0;
  Index too_long = 0;  // collapses refused: a straight segment to the kept vertex longer than √2
  Index no_gain = 0;   // swaps and moves refused: the worst curved quality would not rise
  Index flat = 0;      // refused: a new straight simplex below the straight quality floor
  Index refused = 0;   // refused by the P2 operator otherwise (topology, or no certified curving)

  void add(CavityStatus status);
  CurvedOperationCount& operator+=(const CurvedOperationCount& other);  // (the parts of a distributed run)
};

struct CurvedPass {
  CurvedOperationCount collapses, splits, swaps, moves;
  Index vertices = 0, elements = 0;  // after the pass
  double seconds = 0;
};

struct CurvedAdaptationRun {
  std::vector<CurvedPass> passes;
  bool converged = false;  // a pass changed almost nothing, not stopped at the cap
  P2CavityCounters counters;
  double seconds = 0;
};

// The curved mesh in its metric: edge lengths of the curved edges and the curved mean ratio
// (docs/curving.md §Curved quality) of the elements.
struct CurvedMeasures {
  Index edge_count = 0, element_count = 0;
  double length_min = 0, length_mean = 0, length_max = 0;
  double unit_share = 0;  // share of edges with curved length in [1/√2, √2]
  double quality_min = 0, quality_mean = 0;
};

// The boundary's geometry for the curved passes' boundary operations (null: interior only), and the
// feature angle that classifies its vertices (as the P1 loop's --angle).
template <int D>
struct CurvedPassGeometry {
  const BoundaryGeometry<D>* geometry = nullptr;
  double feature_angle_degrees = 45;
};

// Runs at most `max_passes` curved passes on `mesh` (P2, certified above options.jacobian_floor,
// with its topology), whose metric is `field`; the mesh is compact on return. The passes' scans of
// the whole mesh (curved lengths, curved qualities) run on `threads`; the operations are serial, and
// the output does not depend on the thread count.
template <int D>
CurvedAdaptationRun adapt_curved(Mesh<D>& mesh, const MetricField<D>& field, const P2CavityOptions& options, int max_passes,
                                 int threads = 1, const CurvedPassGeometry<D>& geometry = {});

// Measured on `threads` threads; the same figures for any count. With `skipped` (per edge), the
// edges flagged are not counted (a distributed part's interface edges that another part counts).
template <int D>
CurvedMeasures measure_curved(Mesh<D>& mesh, const MetricField<D>& field, int threads = 1, std::span<const char> skipped = {});

// The measures of two meshes' elements and edges together (the parts of a distributed mesh).
CurvedMeasures merge_curved_measures(const CurvedMeasures& a, const CurvedMeasures& b);

}  // namespace hocav
