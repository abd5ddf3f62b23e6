// The end of a distributed adaptation in its parts, in place of the gather onto rank 0
// (docs/distributed.md §The end in the parts): every process settles its part's boundary, measures
// it, curves it (--order 2) and writes it into the output file in runs, no process holding the whole
// mesh.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "adapt/adaptation_loop.hpp"
#include "adapt/boundary_settling.hpp"
#include "parallel/curving_in_parts.hpp"
#include "parallel/mesh_file_runs.hpp"
#include "report/mesh_statistics.hpp"

namespace hocav {

// What the end did, the same on every process.
struct OutputInParts {
  BoundarySettling settling;                 // the parts' summed (distances, iterations, rounds and time: the largest)
  std::optional<MetricStatistics> measures;  // with settings.measure_output
  std::optional<CurvingInParts> curving;     // with a curving step; its report's counts the file's
  MeshFileCounts counts;                     // of the file written
  double seconds = 0;                        // the slowest process's
  double seconds_curve = 0;                  // the curving's part of it
};

// The curving of the output in the parts (--order 2, docs/distributed.md §Curving in the parts).
template <int D>
struct PartsCurvingStep {
  // The geometry of the adapted boundary (boundary_of_parts), as the serial run makes it of the
  // adapted mesh; null for none. Shared: it may be the adaptation's own (a CAD model, of which one
  // is open at a time).
  PartsGeometryMaker<D> geometry;
  CurvingOptions options;
  CurvedPassesSettings passes;  // adapt --curved's (none by default)
};

// Every process at once, each with its part after the loop (P1, compact, global ids, pinned flags)
// and `metric` around it: the metric at its vertices, which they keep when the boundary settles onto
// `geometry` (may be null; interface vertices frozen, settle_part_boundary), the output's figures in
// it (distributed_metric_statistics), with `curving` the parts curved (curve_in_parts; their curved
// measures with settings.measure_output), then the mesh file `path` in runs (write_mesh_file_runs: a
// Gamma file or a .vtu; P2 when curved) and, unless `vtu` is empty, the .vtu `vtu` in runs
// (write_vtu_runs, with the serial run's curved_vtu_data: the metric sampled from the part's
// vertices' metrics).
template <int D>
OutputInParts finish_adaptation_in_parts(MeshPart<D>& part, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                         const AdaptationSettings& settings, const std::string& path, const std::string& vtu,
                                         const PartsCurvingStep<D>* curving = nullptr);

}  // namespace hocav
