// Temporary output files: short names beside their target (".hocav-<pid>-<n>.tmp<ext>", so that a
// target name of 255 bytes still has a legal temporary), remembered so that SIGINT, SIGTERM and
// SIGHUP remove them before the process dies as the signal asks.
#pragma once

#include <string>

namespace hocav {

// A fresh temporary path in the folder of `target`, ending with the target's extension (writers
// such as gmsh's choose the format by it). Registered for removal on the signals above.
std::string new_temporary_path(const std::string& target);

// Removes the file (if any) and forgets it.
void remove_temporary(const std::string& temporary);

// Forgets a temporary that was renamed into place.
void forget_temporary(const std::string& temporary);

}  // namespace hocav
