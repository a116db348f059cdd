// Picks a UDP port no one on this host is bound to, so two runs never hear
// each other (LCM 1.3.1 binds its port on all addresses).
#pragma once

namespace beft::launch {

// Tries ports from a pid-dependent start within [first, last]; -1 if none.
int findFreeUdpPort(int first = 17000, int last = 19999);

}  // namespace beft::launch
