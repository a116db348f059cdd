// Reads a P/T net in PNML (ISO/IEC 15909-2) with the arbiter's annotations.
//
// Accepted: <place>, <transition>, <arc> anywhere under <net>, nested <page>s
// flattened, <referencePlace>/<referenceTransition> resolved; labels in
// <text> (PNML 2009) or <value> (older files); <name> optional; arc weight in
// <inscription> (default 1); <initialMarking> (default 0). Graphics and other
// tools' <toolspecific> elements are ignored.
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

#include "petri_net.hpp"

namespace beft::arbiter {

// Every problem found in a file, each as "FILE:LINE: message".
class NetError : public std::runtime_error {
 public:
  explicit NetError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

// Throws NetError (also when the file cannot be read).
Net readPnmlFile(const std::string& path);
// The same from text; display_name stands for the file name in messages.
Net readPnmlString(const std::string& text, const std::string& display_name);

}  // namespace beft::arbiter
