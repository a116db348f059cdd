// Runs another program to its end with its output thrown away (the
// benchmarks run whole missions this way and read what they wrote).
#pragma once

#include <string>
#include <vector>

namespace beft {

// args[0] is the program's path. Returns its exit code, or -1 if it could
// not be started or did not exit by itself (a signal).
int runQuietly(std::vector<std::string> args);

}  // namespace beft
