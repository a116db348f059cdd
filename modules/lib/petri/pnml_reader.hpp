// Reads a P/T net in PNML (ISO/IEC 15909-2) with the arbiter's annotations.
//
// Accepted: ISO place/transition nets (type .../grammar/ptnet, with or
// without the PNML namespace or a prefix), ProM's and pm4py's pnmlcoremodel,
// WoPeD's ptNetb, PIPE's files; <place>, <transition>, <arc> anywhere under
// <net> (WoPeD puts them there, without a page), nested <page>s flattened,
// <referencePlace>/<referenceTransition> resolved (chains too); labels in
// <text> (PNML 2009) or <value> (older files, PIPE's "Default,1"); <name>
// optional; arc weight in <inscription> (default 1); <initialMarking>
// (default 0); arcs in any order; any encoding the XML declaration names.
// Graphics and other tools' <toolspecific> elements are ignored.
// Refused with the reason: high-level and symmetric nets, coloured PIPE nets,
// inhibitor, reset and other special arcs, TAPAAL's native format, ids used
// twice.
//
// The arbiter's annotations, in <toolspecific tool="beft" version="1">:
//   on a transition:  <expert>NAME</expert>        the expert it fires
//                     <silent/> or <expert>-</expert>  no expert (join, fork)
//                     <tick/>                      the silent transition that
//                                                  closes a tick (exactly one)
//                     <level>low</level>           free label
//                     <timeout>2.0</timeout>       seconds from FIRE to DONE
//                     <heartbeat_timeout>3</heartbeat_timeout>  seconds
//                     <on_timeout>retry|skip|fail</on_timeout>
//                     <on_failure>retry|skip|fail</on_failure>
//                     <retries>2</retries>         default 1 with a retry policy
//                     <after_retries>skip|fail</after_retries>  default fail
// Anything else inside that element is refused, so a misspelt option is
// never silently ignored.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "lib/petri/petri_net.hpp"

namespace beft::arbiter {

// Every problem found in a file, each as "FILE:LINE: message".
class NetError : public std::runtime_error {
 public:
  explicit NetError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

struct PnmlReadOptions {
  // Which <net> of a file that holds several; "" reads the first (and says so).
  std::string net_id;
  // true (the arbiter): what makes the net no schedule is an error. false
  // (analysis of any P/T net): it goes to Net::schedule_problems instead.
  bool schedule = true;
};

// Throws NetError (also when the file cannot be read).
Net readPnmlFile(const std::string& path, const PnmlReadOptions& options = {});
// The same from text; display_name stands for the file name in messages.
Net readPnmlString(const std::string& text, const std::string& display_name,
                   const PnmlReadOptions& options = {});

}  // namespace beft::arbiter
