// Points and paths in the planners' continuous frame: cell units, cell (x, y)
// covering [x, x+1) x [y, y+1), so a cell's centre is (x + 0.5, y + 0.5).
#pragma once

#include <cmath>
#include <vector>

namespace beft::planners {

struct Point2 {
  double x = 0;
  double y = 0;
};

inline Point2 operator+(Point2 a, Point2 b) { return {a.x + b.x, a.y + b.y}; }
inline Point2 operator-(Point2 a, Point2 b) { return {a.x - b.x, a.y - b.y}; }
inline Point2 operator*(double s, Point2 a) { return {s * a.x, s * a.y}; }
inline double norm(Point2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }
inline double distance(Point2 a, Point2 b) { return norm(a - b); }

inline Point2 cellCentre(int x, int y) { return {x + 0.5, y + 0.5}; }

using Path = std::vector<Point2>;

inline double pathLength(const Path& path) {
  double length = 0;
  for (size_t i = 1; i < path.size(); ++i) length += distance(path[i - 1], path[i]);
  return length;
}

}  // namespace beft::planners
