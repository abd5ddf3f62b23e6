// A .vtu written by every process at once, each its part of a distributed mesh (docs/distributed.md
// §A .vtu in runs): no process holds the whole mesh. The file's points are the parts' points part
// after part, so a vertex that several parts hold is a point of each; ParaView draws the mesh the
// same (its Clean to Grid filter merges them).
#pragma once

#include <string>

#include "io/vtu_file.hpp"

namespace hocav {

// Every process at once: the .vtu at `path` of the meshes every process holds (all P1 or all P2),
// with `data` each (its point fields' rows the mesh's points, its cell fields' its elements): its
// points and cells rank after rank, each array's runs in rank order. One process writes write_vtu's
// file byte for byte. Rank 0 writes the XML with a hole for each array's runs (into the output's
// temporary in the command's OutputSet), then every process writes its runs in place. Throws Error
// naming `path` when a field's rows are wrong or the file cannot be written.
template <int D>
void write_vtu_runs(const std::string& path, const Mesh<D>& mesh, const VtuData& data = {});

}  // namespace hocav
