// The one file that every process of a distributed write fills in place: rank 0 begins it (the
// layout with holes), every process then writes its runs of records into the holes.
#pragma once

#include <string>
#include <vector>

namespace hocav {

// Every process at once, after rank 0 has begun output `path`: the file it wrote, the temporary
// that the command's OutputSet holds for `path`, or `path` itself outside one.
std::string file_begun_on_rank_0(const std::string& path);

// Every process at once: output `path` (through the command's OutputSet, as AtomicOutput writes)
// made of its segments one after another, segment i the processes' `segments[i]` in rank order
// (each process gives as many segments, most of them empty on most processes). Rank 0 begins the
// file with its own segments; every process then writes its own in place. Throws Error when the
// file cannot be written.
void write_segments_in_runs(const std::string& path, const std::vector<std::string>& segments);

}  // namespace hocav
