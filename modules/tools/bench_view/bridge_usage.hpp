// What the viewer's server uses: beft-bridge is started by the run's
// launcher, so it is found by its command line (its --port).
#pragma once

namespace beft::bench {

struct BridgeUsage {
  long rss_kb = -1;     // VmRSS; -1 when no bridge serves the port
  double cpu_s = -1;    // user + system CPU time since it started
};

// The beft-bridge serving `port`, read from /proc now.
BridgeUsage bridgeUsage(int port);

}  // namespace beft::bench
