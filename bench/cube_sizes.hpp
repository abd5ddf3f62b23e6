// The structured cube the benchmarks measure at about a million tetrahedra.
#pragma once

namespace hocav {

inline constexpr int kMillionCubeCellsPerSide = 55;  // 6 * 55^3 = 998,250 tetrahedra

}  // namespace hocav
