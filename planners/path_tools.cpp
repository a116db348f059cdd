#include "planners/path_tools.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace beft::planners {

bool pathFree(const PlanningMap& map, const Path& path) {
  if (path.empty()) return false;
  if (path.size() == 1) return map.pointFree(path.front());
  for (size_t i = 1; i < path.size(); ++i) {
    if (!map.segmentFree(path[i - 1], path[i])) return false;
  }
  return true;
}

Path removeDuplicatePoints(const Path& path) {
  Path out;
  for (const Point2& p : path) {
    if (out.empty() || distance(out.back(), p) > 1e-9) out.push_back(p);
  }
  return out;
}

Path shortcutPath(const PlanningMap& map, const Path& input) {
  const Path path = removeDuplicatePoints(input);
  if (path.size() <= 2) return path;
  Path out{path.front()};
  size_t anchor = 0;
  while (anchor + 1 < path.size()) {
    // Extend the line of sight while it stays free; a few blocked points are
    // skipped so that small wiggles of the input do not end the look-ahead.
    size_t best = anchor + 1;
    int misses = 0;
    for (size_t next = anchor + 2; next < path.size(); ++next) {
      if (map.segmentFree(path[anchor], path[next])) {
        best = next;
        misses = 0;
      } else if (++misses > 8) {
        break;
      }
    }
    out.push_back(path[best]);
    anchor = best;
  }
  return out;
}

Path tightenPath(const PlanningMap& map, const Path& input, int passes) {
  Path path = shortcutPath(map, input);
  for (int pass = 0; pass < passes && path.size() > 2; ++pass) {
    const double before = pathLength(path);
    Path out{path.front()};
    for (size_t i = 1; i + 1 < path.size(); ++i) {
      const Point2 a = out.back();
      const Point2 v = path[i];
      const Point2 b = path[i + 1];
      if (map.segmentFree(a, b)) continue;  // v is not needed
      // The widest cut of the corner at v: points at fraction t of the way
      // from v back to a and on to b. Cuts shorter than 1e-3 cells are not worth it.
      double good = 0, bad = 1;
      for (int k = 0; k < 12; ++k) {
        const double t = 0.5 * (good + bad);
        if (map.segmentFree(v + t * (a - v), v + t * (b - v))) good = t; else bad = t;
      }
      const Point2 p1 = v + good * (a - v);
      const Point2 p2 = v + good * (b - v);
      if (good * std::min(distance(a, v), distance(v, b)) < 1e-3 || !map.segmentFree(a, p1) ||
          !map.segmentFree(p2, b)) {
        out.push_back(v);
        continue;
      }
      out.push_back(p1);
      out.push_back(p2);
    }
    out.push_back(path.back());
    path = shortcutPath(map, out);
    if (before - pathLength(path) < 1e-6) break;
  }
  return path;
}

double totalTurning(const Path& input) {
  const Path path = removeDuplicatePoints(input);
  double turning = 0;
  for (size_t i = 1; i + 1 < path.size(); ++i) {
    const Point2 a = path[i] - path[i - 1];
    const Point2 b = path[i + 1] - path[i];
    const double angle = std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
    turning += std::abs(angle);
  }
  return turning;
}

double minClearance(const PlanningMap& map, const Path& path, double step) {
  if (path.empty()) return 0;
  double best = map.clearance(path.front());
  for (size_t i = 1; i < path.size(); ++i) {
    const double length = distance(path[i - 1], path[i]);
    const int samples = std::max(1, static_cast<int>(std::ceil(length / step)));
    for (int k = 1; k <= samples; ++k) {
      const double t = static_cast<double>(k) / samples;
      best = std::min(best, map.clearance(path[i - 1] + t * (path[i] - path[i - 1])));
    }
  }
  return best;
}

std::vector<double> travelHeadings(const Path& path, double goal_heading) {
  std::vector<double> headings(path.size(), goal_heading);
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Point2 d = path[i + 1] - path[i];
    headings[i] = std::atan2(d.y, d.x);
  }
  return headings;
}

}  // namespace beft::planners
