// The parameters each process of a run was started with (its --param
// NAME=VALUE arguments), kept beside the run's log as parameters.json, so
// that `beft replay --module NAME` runs the expert as it ran: a run made with
// --acoustics binaural or --set stop_when_done=0 replays exactly without
// the user retyping them.
#pragma once

#include <map>
#include <string>

#include "lib/launch/launch_file.hpp"

namespace beft::launch {

inline constexpr const char* kRunParametersFile = "parameters.json";

// {"process": {"NAME": "VALUE", ...}, ...} for every process of the spec.
std::string runParametersJson(const LaunchSpec& spec);

// Writes runParametersJson to path; false if it cannot be written.
bool writeRunParameters(const LaunchSpec& spec, const std::string& path);

// The parameters of one process from such a file; empty when the file does
// not exist or does not name the process. Throws std::runtime_error naming
// the file when it exists but is not such a file.
std::map<std::string, std::string> readRunParameters(const std::string& path, const std::string& process);

}  // namespace beft::launch
