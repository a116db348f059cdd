// Where the running program lives, so launchers start their siblings from the
// same build rather than whatever PATH holds.
#pragma once

#include <string>

namespace beft {

// The folder of this process's executable ("." if it cannot be read).
std::string ownBinDir();

}  // namespace beft
