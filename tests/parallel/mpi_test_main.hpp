// The main of an MPI test run by ctest under `mpirun -np N`: `check` runs on every process (each
// saying what fails on stderr), and the test passes when it holds on all of them; an exception on
// one ends them all (the others would wait for it).
#pragma once

#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "parallel/communicator.hpp"

namespace hocav {

template <typename Check>
int run_mpi_test(int argc, char** argv, const std::string& name, Check&& check) {
  MpiSession mpi(argc, argv);
  if (process_count() < 2) {
    std::cerr << name << ": run it under mpirun with 2 or more processes\n";
    return 1;
  }
  try {
    const bool ok = check();
    const std::vector<char> all = all_gather_value(static_cast<char>(ok));
    return std::all_of(all.begin(), all.end(), [](char each) { return each != 0; }) ? 0 : 1;
  } catch (const std::exception& error) {
    std::cerr << name << ": rank " << process_rank() << ": " << error.what() << '\n';
    abort_processes(1);
  }
}

}  // namespace hocav
