// Where processes meet: the LCM URL, shared by every binary's --lcm-url flag.
#pragma once

#include <string>

namespace beft {

// Traffic stays on this host (ttl=0). BEFT_LCM_URL overrides the default, and
// --lcm-url overrides both. Runs isolate themselves by UDP port.
std::string defaultLcmUrl();

// The URL for a given port on the default multicast group, host-local.
std::string lcmUrlForPort(int port, int ttl = 0);

}  // namespace beft
