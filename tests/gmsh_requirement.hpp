// Tests of what needs gmsh (the gmsh-meshed annulus and sphere-shell cases, CAD models) skip with a
// message in a build without it (CMake option HOCAV_WITH_GMSH=OFF, passed to the test binaries).
#pragma once

#include <gtest/gtest.h>

// Use as the first statement of a test body or fixture SetUp.
#define HOCAV_SKIP_WITHOUT_GMSH()                                                                      \
  do {                                                                                                 \
    if (!HOCAV_WITH_GMSH) GTEST_SKIP() << "needs gmsh: this hocav was built with HOCAV_WITH_GMSH=OFF"; \
  } while (false)
