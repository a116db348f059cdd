// The text of every .lcm file of lcmtypes/, compiled into the library.
#pragma once

#include <string>
#include <vector>

namespace beft::wire {

struct EmbeddedSchema {
  std::string file;  // e.g. "robot_state_t.lcm"
  std::string text;
};

const std::vector<EmbeddedSchema>& embeddedLcmSchemas();

}  // namespace beft::wire
