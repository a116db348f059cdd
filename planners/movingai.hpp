// MovingAI grid benchmark files (Sturtevant 2012): `.map` octile maps and
// `.map.scen` query lists. x is the column, y the row, row 0 the top row.
#pragma once

#include "planners/grid_map.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace beft::planners {

// A file that cannot be read or does not follow the format: "FILE:LINE: what".
class MapFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MovingAiQuery {
  int bucket = 0;
  std::string map;  // map name as written in the file
  int map_width = 0, map_height = 0;
  int start_x = 0, start_y = 0, goal_x = 0, goal_y = 0;
  double optimal_length = 0;  // octile optimum; 0 with start != goal: unreachable
  int line = 0;               // line in the .scen file
  bool reachable() const {
    return optimal_length > 0 || (start_x == goal_x && start_y == goal_y);
  }
};

// Passable: . G S; blocked: @ O T W. CRLF line endings are accepted.
GridMap loadMovingAiMap(const std::string& path);
std::vector<MovingAiQuery> loadMovingAiScenario(const std::string& path);

}  // namespace beft::planners
