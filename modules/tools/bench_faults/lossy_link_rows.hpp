// The rows of beft-bench-faults over two hosts (two network namespaces,
// tests/system/two_hosts.hpp): the yard mission with the experts on the
// other host, over a link that drops a share of the datagrams each way, one
// run per loss on the same two hosts; each compared with the clean run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lib/compare/run_log.hpp"
#include "tools/bench_faults/outcome.hpp"

namespace beft::bench {

struct LinkRuns {
  std::vector<double> losses;  // each way [0..1]
  std::string work;            // the runs go to work/link_<percent>
  uint64_t seed = 0;           // the clean run's
  int ticks = 0;
};

// One row per loss; rows that cannot run here (no root, no namespaces, no
// iptables) say "skipped: " and why.
std::vector<Outcome> runOverLossyLink(const LinkRuns& runs, const std::vector<compare::LoggedMessage>& clean);

// "ticks/s at 5 % loss / at 0 % loss on the same two hosts: R" from the rows
// with those losses; "" when either is missing.
std::string speedRatioLine(const std::vector<Outcome>& rows, double lossy, double clean);

}  // namespace beft::bench
