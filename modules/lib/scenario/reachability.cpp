#include "lib/scenario/reachability.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "lib/scenario/footprint.hpp"

namespace beft::scenario {

namespace {

// Cells [first, last] along one axis covering [low, high] metres, clamped.
std::pair<int, int> cellSpan(double low, double high, double resolution, int cells) {
  const int first = std::max(0, static_cast<int>(std::floor(low / resolution)));
  const int last = std::min(cells - 1, static_cast<int>(std::floor(high / resolution)));
  return {first, last};
}

// Half the diagonal of the object's footprint: a disc around its centre holding it.
double footprintRadius(const Visual& visual) {
  if (visual.shape == Visual::Shape::Cylinder) return visual.radius;
  return 0.5 * std::hypot(visual.size_x, visual.size_y);
}

}  // namespace

ReachableSpace::ReachableSpace(const Scenario& scenario, const ReachabilityOptions& options)
    : resolution_(scenario.world.resolution), options_(options) {
  width_ = std::max(1, static_cast<int>(std::ceil(scenario.world.width / resolution_)));
  height_ = std::max(1, static_cast<int>(std::ceil(scenario.world.height / resolution_)));
  std::vector<char> blocked(static_cast<std::size_t>(width_) * height_, 0);
  for (const Object& object : scenario.objects) {
    if (!object.visual) continue;
    const double extent = footprintRadius(*object.visual) + options.clearance;
    const auto [col0, col1] = cellSpan(object.x - extent, object.x + extent, resolution_, width_);
    const auto [row0, row1] = cellSpan(object.y - extent, object.y + extent, resolution_, height_);
    for (int row = row0; row <= row1; ++row) {
      for (int col = col0; col <= col1; ++col) {
        const double x = (col + 0.5) * resolution_, y = (row + 0.5) * resolution_;
        if (distanceToFootprint(object, x, y) <= options.clearance) blocked[row * width_ + col] = 1;
      }
    }
  }
  // The world's edge is a wall too: the footprint cannot leave the world.
  const int margin = static_cast<int>(std::ceil(options.clearance / resolution_));
  for (int row = 0; row < height_; ++row) {
    for (int col = 0; col < width_; ++col) {
      if (row < margin || col < margin || row >= height_ - margin || col >= width_ - margin) {
        blocked[row * width_ + col] = 1;
      }
    }
  }

  reachable_.assign(blocked.size(), 0);
  const int start = cellIndex(scenario.robot.x, scenario.robot.y);
  if (start < 0 || blocked[start]) return;
  std::deque<int> open{start};
  reachable_[start] = 1;
  while (!open.empty()) {
    const int cell = open.front();
    open.pop_front();
    ++reachable_cells_;
    const int col = cell % width_, row = cell / width_;
    const int neighbours[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& step : neighbours) {
      const int c = col + step[0], r = row + step[1];
      if (c < 0 || r < 0 || c >= width_ || r >= height_) continue;
      const int next = r * width_ + c;
      if (blocked[next] || reachable_[next]) continue;
      reachable_[next] = 1;
      open.push_back(next);
    }
  }
}

int ReachableSpace::cellIndex(double x, double y) const {
  const int col = static_cast<int>(std::floor(x / resolution_));
  const int row = static_cast<int>(std::floor(y / resolution_));
  if (col < 0 || row < 0 || col >= width_ || row >= height_) return -1;
  return row * width_ + col;
}

bool ReachableSpace::isReachableAt(double x, double y) const {
  const int cell = cellIndex(x, y);
  return cell >= 0 && reachable_[cell];
}

bool ReachableSpace::canReach(const Object& object) const {
  const double extent =
      (object.visual ? footprintRadius(*object.visual) : 0.0) + options_.reach_distance;
  const auto [col0, col1] = cellSpan(object.x - extent, object.x + extent, resolution_, width_);
  const auto [row0, row1] = cellSpan(object.y - extent, object.y + extent, resolution_, height_);
  for (int row = row0; row <= row1; ++row) {
    for (int col = col0; col <= col1; ++col) {
      if (!reachable_[row * width_ + col]) continue;
      const double x = (col + 0.5) * resolution_, y = (row + 0.5) * resolution_;
      const double distance =
          object.visual ? distanceToFootprint(object, x, y) : std::hypot(x - object.x, y - object.y);
      if (distance <= options_.reach_distance) return true;
    }
  }
  return false;
}

std::vector<std::string> unreachablePersons(const Scenario& scenario, const ReachabilityOptions& options) {
  const ReachableSpace space(scenario, options);
  std::vector<std::string> unreachable;
  for (const Object& object : scenario.objects) {
    if (object.label == "person" && !space.canReach(object)) unreachable.push_back(object.id);
  }
  return unreachable;
}

}  // namespace beft::scenario
