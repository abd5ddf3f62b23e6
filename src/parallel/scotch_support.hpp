// What the serial and the distributed partitions share of Scotch (docs/distributed.md
// §Partitioning): the int64 build, its errors as exceptions, a context that makes it deterministic,
// a strategy. Included after mpi.h by the distributed one (ptscotch.h includes scotch.h).
#pragma once

#include <stdint.h>  // scotch.h needs int64_t and FILE
#include <stdio.h>

#include <scotch.h>

#include <cstdint>
#include <string>

#include "base/error.hpp"

namespace hocav {

static_assert(sizeof(SCOTCH_Num) == sizeof(std::int64_t), "hocav needs Scotch's int64 build (scotch-int64)");

inline void check_scotch(int status, const char* what) {
  if (status != 0) throw Error(std::string("Scotch failed in ") + what);
}

// A context that makes Scotch deterministic (its threads otherwise race) with a fixed random seed
// (`seed`, or Scotch's own for 0).
struct ScotchContext {
  SCOTCH_Context context;
  explicit ScotchContext(std::int64_t seed) {
    check_scotch(SCOTCH_contextInit(&context), "SCOTCH_contextInit");
    check_scotch(SCOTCH_contextOptionSetNum(&context, SCOTCH_OPTIONNUMDETERMINISTIC, 1), "SCOTCH_contextOptionSetNum");
    check_scotch(SCOTCH_contextOptionSetNum(&context, SCOTCH_OPTIONNUMRANDOMFIXEDSEED, 1), "SCOTCH_contextOptionSetNum");
    if (seed != 0) SCOTCH_contextRandomSeed(&context, static_cast<SCOTCH_Num>(seed));
    SCOTCH_contextRandomReset(&context);
  }
  ~ScotchContext() { SCOTCH_contextExit(&context); }
};

struct ScotchStrategy {
  SCOTCH_Strat strategy;
  ScotchStrategy() { check_scotch(SCOTCH_stratInit(&strategy), "SCOTCH_stratInit"); }
  ~ScotchStrategy() { SCOTCH_stratExit(&strategy); }
};

}  // namespace hocav
