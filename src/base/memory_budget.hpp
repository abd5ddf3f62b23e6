// The memory a job will need, checked against the machine before the job starts: a job that cannot
// fit fails at once, with its estimate, instead of after minutes with std::bad_alloc.
#pragma once

#include <string>

namespace hocav {

// Bytes per element of a job, from the peak resident memory measured in docs/benchmarks.md (the
// whole curving run: 282–330 bytes per tetrahedron past 1M elements, up to 860 on small meshes),
// rounded up.
inline constexpr double kMeshBytesPerElement = 200;     // a P1 mesh with its topology, being built or written
inline constexpr double kMetricBytesPerElement = 300;   // the mesh, its metric and the source's work arrays
inline constexpr double kCurvingBytesPerElement = 600;  // P1 back mesh, P2 mesh, metric field, cavities
// Per output element of `hocav adapt`: the loop's peak (190 MB for 306k output elements on the
// sphere shell, its passes overshooting to 490k) then the curving of the output.
inline constexpr double kAdaptationBytesPerElement = 620 + kCurvingBytesPerElement;

// The process's peak resident memory so far (getrusage), in bytes.
long long peak_resident_bytes();

// The machine's physical memory (sysconf), in bytes.
double physical_memory_bytes();

// Throws Error "<job>: about N elements would need about X GB, more than the Y GB of this machine"
// when elements * bytes_per_element exceeds the physical memory, or when the count exceeds the
// 32-bit indices of the mesh.
void check_memory_fits(const std::string& job, double elements, double bytes_per_element);

}  // namespace hocav
