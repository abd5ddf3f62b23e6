// Layers bent with their wall (docs/curving.md, "Layers bent with their wall"): on a boundary layer
// the first layer can be thinner than a wall edge's sag, so the wall's node cannot reach the
// geometry while the edges above it stay where they are. A bend moves the wall's nodes around the
// edge to their proposals and the nodes of the volume edges above them by the wall's P2
// displacement at their foot, faded to zero at a reach of a few times the wall edges' bow. Every
// element holding a moved node is certified (and keeps most of its quality in the metric); a
// failing bend moves by the largest common fraction that certifies (bisection), or not at all.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "metric/metric_field.hpp"
#include "surface/boundary_proposals.hpp"

namespace hocav {

template <int D>
struct LayerBendOptions {
  double jacobian_floor = 0.01;
  // With a metric, each element a bend changes also keeps its curved quality (docs/curving.md §Curved
  // quality) at least max(0.7 q, min(q, 0.1)), q its quality before, as the boundary settling does.
  const MetricField<D>* field = nullptr;
  int correction_steps = 4;  // bisection steps of the common fraction
  double reach_in_bows = 4;  // the volume's moves fade to zero this many times the wall edges' bow from the wall
};

struct LayerBend {
  double fraction = 0;                           // of every move, 1 when the bend was made in full
  std::vector<std::array<Index, 2>> wall_edges;  // the wall edges moved toward their proposals
  Index volume_nodes = 0;                        // volume edges' nodes moved
  long long elements_certified = 0;
};

// Bends the layers around boundary edge (a, b), whose proposal is not placed yet. The mesh must be
// P2 with its topology and its elements above the floor; it stays so.
template <int D>
LayerBend bend_layers(Mesh<D>& mesh, const BoundaryProposals<D>& proposals, Index a, Index b, const LayerBendOptions<D>& options);

}  // namespace hocav
