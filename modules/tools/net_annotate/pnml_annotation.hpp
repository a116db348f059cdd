// Writes the arbiter's annotations (<toolspecific tool="beft" version="1">)
// into a PNML file drawn in an editor, keeping everything else in it, so
// the result still opens in that editor and the arbiter runs it.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace beft::net_annotate {

struct AnnotationRequest {
  std::map<std::string, std::string> experts;  // transition id or name -> expert
  std::string tick;                            // transition id or name
  std::vector<std::string> silent;             // transitions that fire no expert
  std::map<std::string, std::string> levels;   // transition -> free label
  std::string net_id;                          // "" for the first <net>
};

struct AnnotationResult {
  std::string text;                    // the annotated file, UTF-8
  std::vector<std::string> made_silent;  // transitions not named, made silent
  std::vector<std::string> kept;         // already annotated and not named: left as they were
};

// Throws std::runtime_error naming the file, line and problem: a
// transition asked for that the net does not have, a name that fits two
// transitions, a transition given two roles.
AnnotationResult annotatePnml(const std::string& bytes, const std::string& display_name,
                              const AnnotationRequest& request);

}  // namespace beft::net_annotate
