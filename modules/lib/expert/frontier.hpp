// What a firing comes after. An expert's outputs and its DONE travel
// separately: when an output is lost on the way and the DONE is not, the
// arbiter fires the next expert, which would read the output's previous
// value (a latest-value input such as ROBOT_CMD has no tick to wait for).
// So every DONE lists what its expert had published (sender id and last
// sequence number per data channel), the arbiter sends what changed as a
// FRONTIER message before the next firing, and every FIRE names the
// FRONTIER message it comes after. Here the expert keeps what the FRONTIER
// messages listed, and a firing waits until its receivers hold all of it on
// the channels they take (the transport asks for what is missing): causal
// order, as vector clocks give it, for the price of a short message a step.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/frontier_t.hpp>

#include "lib/transport/transport.hpp"

namespace lcm {
class LCM;
}

namespace beft::expert {

class Frontier {
 public:
  // A FRONTIER message: its entries join what is known (a later number wins).
  void add(const beft::frontier_t& frontier);

  // Whether `receivers` (null ones left out) hold the FRONTIER message
  // `fire` comes after and every message listed so far. When not, the
  // transport asks for what is missing; call again after draining.
  // `restarted`: this process was restarted mid-run and rebuilt its state
  // from the run's log, so what it has not heard since is not awaited.
  bool reached(const beft::fire_t& fire, std::initializer_list<transport::Receiver*> receivers,
               bool restarted = false) const;

  std::size_t entries() const { return latest_.size(); }

 private:
  std::map<std::pair<int64_t, std::string>, int64_t> latest_;  // (sender, plain channel) -> sequence
};

// Fills a DONE's `sender` and published lists with what this process has
// published on `lcm` on data-plane channels.
void listPublished(lcm::LCM& lcm, beft::done_t& done);

}  // namespace beft::expert
