// Frontier-based exploration: known free cells next to unknown ones, grouped
// into connected frontiers; the robot goes to the nearest reachable one,
// facing the unknown side.
//
// Two kinds of unknown cells do not make a frontier: those near a place the
// robot has stood (the camera cannot see the ground right around the robot,
// but the robot stood there), and frontier cells near a frontier goal already
// visited (what stayed unknown from there cannot be seen from there).
#pragma once

#include <optional>
#include <vector>

#include "experts/exploration/known_map.hpp"
#include "experts/exploration/viewpoints.hpp"

namespace beft::exploration {

struct FrontierParameters {
  int min_cells = 5;               // smaller frontiers are noise
  double blind_radius_m = 2.2;     // unknown cells this close to where the robot stood are not a frontier
  double visited_radius_m = 1.5;   // frontier cells this close to a visited goal are ignored
  double size_gain = 0.1;          // [m of travel saved per m of frontier length]
  double facing_radius_m = 3.0;    // the goal faces the unknown cells within this
};

// Where the robot has stood and which frontier goals it visited, kept as
// masks over the map's cells (stamped once per point, rebuilt only when the
// map's geometry changes).
class ExplorationMemory {
 public:
  explicit ExplorationMemory(FrontierParameters parameters = {}) : parameters_(parameters) {}
  void addStood(Point p) { stood_.push_back(p); }
  void addVisited(Point p) { visited_.push_back(p); }
  const std::vector<Point>& stood() const { return stood_; }
  const std::vector<Point>& visited() const { return visited_; }
  const FrontierParameters& parameters() const { return parameters_; }

  // Brings the masks up to date for this map.
  void prepare(const KnownMap& map);
  // After prepare(map):
  bool unknownIgnored(int x, int y) const { return ignored_unknown_[index(x, y)] != 0; }
  bool frontierIgnored(int x, int y) const { return ignored_frontier_[index(x, y)] != 0; }

 private:
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }

  FrontierParameters parameters_;
  std::vector<Point> stood_, visited_;
  int width_ = -1, height_ = -1;
  double resolution_ = 0, origin_x_ = 0, origin_y_ = 0;
  size_t stood_stamped_ = 0, visited_stamped_ = 0;
  std::vector<uint8_t> ignored_unknown_, ignored_frontier_;
};

struct FrontierGoal {
  double x = 0, y = 0;    // a standable, reachable frontier cell [m]
  double yaw = 0;         // facing the unknown cells beyond it [deg]
  double travel_m = 0;    // [m]
  int size = 0;           // cells in the frontier
  double cost = 0;        // [m]
};

// True when cell (x, y) is a frontier cell: free, not near a visited goal, and
// 4-adjacent to an unknown cell not near where the robot stood.
bool isFrontierCell(const KnownMap& map, const ExplorationMemory& memory, int x, int y);

// Every frontier of at least min_cells cells, each in the order its cells
// were found (row by row). Calls memory.prepare(map).
std::vector<std::vector<Cell>> frontierClusters(const KnownMap& map, ExplorationMemory& memory);

// Every reachable frontier, cheapest first (the first found of equals).
// Calls memory.prepare(map).
std::vector<FrontierGoal> findFrontiers(const KnownMap& map, const TravelField& travel, ExplorationMemory& memory);

// findFrontiers' first, searched outwards from the robot (the travel field
// of the robot at `robot`): far frontiers are not reached for when a near
// one is cheaper than they can be.
std::optional<FrontierGoal> cheapestFrontier(const KnownMap& map, const TravelField& travel,
                                             ExplorationMemory& memory, Point robot);

// True while some frontier cell remains within radius of (x, y).
bool frontierNear(const KnownMap& map, ExplorationMemory& memory, double x, double y, double radius);

}  // namespace beft::exploration
