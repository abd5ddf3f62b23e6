// The one file that every process of a distributed write fills in place: rank 0 begins it (the
// layout with holes), every process then writes its runs of records into the holes.
#pragma once

#include <string>

namespace hocav {

// Every process at once, after rank 0 has begun output `path`: the file it wrote, the temporary
// that the command's OutputSet holds for `path`, or `path` itself outside one.
std::string file_begun_on_rank_0(const std::string& path);

}  // namespace hocav
