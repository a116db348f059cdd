// The key of an authenticated run (lib/transport/message_key.hpp): the file
// given with --key, else the one BEFT_KEY_FILE names. The launcher checks it
// before anything starts and hands every process its absolute path as
// BEFT_KEY_FILE (supervisor.hpp); the key itself is never printed.
#pragma once

#include <string>

namespace beft::launch {

// The absolute path of the run's key file: `option` when given, else
// BEFT_KEY_FILE; "" for a run without a key. Sets BEFT_KEY_FILE to it, so
// that the launcher's own LCM instances (a planned kill follows the run's
// ticks; another host listens for the run's beacons) use the key too.
// Throws LaunchError, naming the file, when it cannot be read or holds no key.
std::string runKeyFile(const std::string& option);

}  // namespace beft::launch
