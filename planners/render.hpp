// Pictures of a planning problem: free cells white, obstacles black, the
// robot-radius inflation grey, particle traces light blue, the path red with
// its waypoints and their headings, start green, goal blue.
#pragma once

#include "planners/geometry.hpp"
#include "planners/planning_map.hpp"

#include <opencv2/core.hpp>

#include <vector>

namespace beft::planners {

struct RenderOptions {
  int scale = 0;          // pixels per cell; 0 picks one for ~800 px
  bool y_up = false;      // true: row 0 at the bottom (world maps); false: at the top (MovingAI)
  bool headings = true;   // draw a heading arrow at each waypoint
};

cv::Mat renderPlan(const PlanningMap& map, const Path& path, const std::vector<Path>& particles, Point2 start,
                   Point2 goal, const std::vector<double>& headings_rad = {}, const RenderOptions& options = {});

// Several plans to one goal on one map (the paper's Fig. 3): each path with
// a dot at every `every`-th waypoint and an arrow for its heading; every
// particle trace behind them.
struct DrawnPlan {
  Path path;
  std::vector<double> headings_rad;
  Point2 start;
  size_t every = 1;
};
cv::Mat renderPlans(const PlanningMap& map, const std::vector<DrawnPlan>& plans, const std::vector<Path>& particles,
                    Point2 goal, const RenderOptions& options = {});

// Writes a picture; throws std::runtime_error naming the file on failure.
void writePng(const std::string& file, const cv::Mat& image);

}  // namespace beft::planners
