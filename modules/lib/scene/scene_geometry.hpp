// The scene's solid geometry: every object with a <visual> as a vertical box
// (oriented by yaw) or cylinder standing on its base height, in a uniform 2-D
// grid so rays and segments only meet the objects near them.
//
// Usable wherever the scene is known: the world builds it from its state, the
// experts from a GT_OBJECTS message (fromMessage), tests from a Scenario.
// Object indices are positions in the ground-truth object list (scenario file
// order), including objects without a visual; those have no solid.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Core>

namespace beft {
struct scene_objects_t;
}
namespace beft::scenario {
struct Scenario;
struct Object;
}  // namespace beft::scenario

namespace beft::camera {

// Which face a line enters a solid through (for shading normals).
enum class Face : uint8_t { Inside, BoxX, BoxY, Cap, Round };

struct Solid {
  enum class Shape : uint8_t { Box, Cylinder };
  Shape shape = Shape::Box;
  int object_index = -1;            // index into the ground-truth object list
  double x = 0, y = 0;              // footprint centre [m]
  double z_min = 0, z_max = 0;      // base and top [m]
  double cos_yaw = 1, sin_yaw = 0;  // box orientation
  double half_x = 0, half_y = 0;    // box half extents along its own axes [m]
  double radius = 0;                // cylinder radius [m]
  uint32_t color_rgb = 0x808080;    // 0xRRGGBB
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;  // footprint bounding rectangle [m]
};

// The part of the line o + t d inside a solid: t in [enter, exit].
struct LineInterval {
  double enter = 0, exit = 0;
  Face enter_face = Face::Inside;  // Inside: the line starts inside (enter = -inf)
};

// Intersects the line o + t d (d need not be unit length) with a solid.
inline bool intersectLine(const Solid& solid, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                          LineInterval& interval);
// Outward unit normal where a line with direction d enters a solid through
// `face` at `point`.
Eigen::Vector3d entryNormal(const Solid& solid, const Eigen::Vector3d& point, const Eigen::Vector3d& d, Face face);
// Signed horizontal distance from (x, y) to a solid's footprint: negative inside.
double footprintDistance(const Solid& solid, double x, double y);

class SceneGeometry {
 public:
  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

  // The scenario's objects at their initial positions.
  static SceneGeometry fromScenario(const scenario::Scenario& scenario);
  // Objects in list order (e.g. the world's current object states).
  static SceneGeometry fromObjects(const std::vector<scenario::Object>& objects);
  // A GT_OBJECTS message. Objects whose shape is SHAPE_NONE or whose sizes are
  // not finite and positive get no solid.
  static SceneGeometry fromMessage(const beft::scene_objects_t& message);

  // Building by hand: set the object count, add solids, then buildIndex().
  // Sizes are full extents; yaw in degrees. Non-finite or non-positive sizes
  // throw std::invalid_argument.
  void setObjectCount(int count);
  void addBox(int object_index, double x, double y, double z, double yaw_deg, double size_x, double size_y,
              double size_z, uint32_t color_rgb = 0x808080);
  void addCylinder(int object_index, double x, double y, double z, double radius, double height,
                   uint32_t color_rgb = 0x808080);
  // Builds the grid; cell_size <= 0 picks one from the scene's extent and
  // object count. Queries before this see no solid.
  void buildIndex(double cell_size = 0);

  int objectCount() const { return object_count_; }
  const std::vector<Solid>& solids() const { return solids_; }
  // Index into solids() of an object's solid, or -1 if it has none.
  int solidOfObject(int object_index) const;
  double cellSize() const { return cell_size_; }

  struct RayHit {
    int solid = -1;  // index into solids(), -1 if nothing
    double t = kInfinity;
    Face face = Face::Inside;
  };
  // The nearest solid the line o + t d enters with t in [t_min, t_max]; ties
  // go to the lower solid index. Walks the grid cells under the ray.
  RayHit firstHit(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_min, double t_max) const;
  // The same answer by testing every solid (the baseline for benchmarks/tests).
  RayHit firstHitBruteForce(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_min,
                            double t_max) const;

  // Solids whose footprint lies within `radius` of (x, y) (by bounding
  // rectangle; may include a few farther ones). Appends solid indices, no
  // duplicates, ascending.
  void solidsNear(double x, double y, double radius, std::vector<int>& out) const;

  // Calls visit(solid_index) for every solid listed in a grid cell that the
  // horizontal projection of o + t d crosses for t in [t_min, t_max], cell by
  // cell in ray order (a solid spanning several cells is visited once per
  // cell). visit returns false to stop.
  template <typename Visit>
  void forEachSolidAlong(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_min, double t_max,
                         Visit&& visit) const;

 private:
  // Walks the cells; visitCell(first, last, t_cell_exit) gets the cell's list
  // [first, last) and returns false to stop.
  template <typename VisitCell>
  void traverseCells(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_min, double t_max,
                     VisitCell&& visit_cell) const;

  int object_count_ = 0;
  std::vector<Solid> solids_;
  std::vector<int> solid_of_object_;
  // Uniform grid over the bounding rectangle of all footprints.
  double cell_size_ = 1, grid_x0_ = 0, grid_y0_ = 0;
  int grid_nx_ = 0, grid_ny_ = 0;
  std::vector<int> cell_start_;  // cell c lists cell_items_[cell_start_[c] .. cell_start_[c + 1])
  std::vector<int> cell_items_;  // solid indices, ascending within a cell
};

// Whether the segment a -> b passes through any object's solid except
// `ignore_object` (an object index, -1 for none). Touching counts.
bool segmentBlocked(const SceneGeometry& scene, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    int ignore_object = -1);
// The object the segment a -> b passes through first (nearest a), ignoring
// `ignore_object`; -1 if none.
int segmentHitsObject(const SceneGeometry& scene, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      int ignore_object = -1);

// ---- inline and template implementations ----

namespace detail {
// Narrows [enter, exit] to where lo <= origin + t * dir <= hi.
inline bool clipSlab(double origin, double dir, double lo, double hi, Face face, LineInterval& interval) {
  if (dir == 0) return origin >= lo && origin <= hi;
  const double inv = 1.0 / dir;
  double t1 = (lo - origin) * inv, t2 = (hi - origin) * inv;
  if (t1 > t2) std::swap(t1, t2);
  if (t1 > interval.enter) {
    interval.enter = t1;
    interval.enter_face = face;
  }
  if (t2 < interval.exit) interval.exit = t2;
  return interval.enter <= interval.exit;
}
}  // namespace detail

inline bool intersectLine(const Solid& solid, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                          LineInterval& interval) {
  interval.enter = -std::numeric_limits<double>::infinity();
  interval.exit = std::numeric_limits<double>::infinity();
  interval.enter_face = Face::Inside;
  const double ox = o.x() - solid.x, oy = o.y() - solid.y;
  if (solid.shape == Solid::Shape::Box) {
    // In the box's own frame (rotated by -yaw).
    const double c = solid.cos_yaw, s = solid.sin_yaw;
    const double lox = c * ox + s * oy, loy = -s * ox + c * oy;
    const double ldx = c * d.x() + s * d.y(), ldy = -s * d.x() + c * d.y();
    return detail::clipSlab(o.z(), d.z(), solid.z_min, solid.z_max, Face::Cap, interval) &&
           detail::clipSlab(lox, ldx, -solid.half_x, solid.half_x, Face::BoxX, interval) &&
           detail::clipSlab(loy, ldy, -solid.half_y, solid.half_y, Face::BoxY, interval);
  }
  // Cylinder: inside the infinite vertical cylinder, then between the caps.
  const double a = d.x() * d.x() + d.y() * d.y();
  const double c = ox * ox + oy * oy - solid.radius * solid.radius;
  if (a == 0) {
    if (c > 0) return false;
  } else {
    const double half_b = ox * d.x() + oy * d.y();
    const double discriminant = half_b * half_b - a * c;
    if (discriminant < 0) return false;
    const double root = std::sqrt(discriminant);
    interval.enter = (-half_b - root) / a;
    interval.exit = (-half_b + root) / a;
    interval.enter_face = Face::Round;
  }
  return detail::clipSlab(o.z(), d.z(), solid.z_min, solid.z_max, Face::Cap, interval);
}

template <typename VisitCell>
void SceneGeometry::traverseCells(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_min,
                                  double t_max, VisitCell&& visit_cell) const {
  if (grid_nx_ == 0 || !(t_min <= t_max) || !o.allFinite() || !d.allFinite()) return;
  const double x1 = grid_x0_ + grid_nx_ * cell_size_, y1 = grid_y0_ + grid_ny_ * cell_size_;
  // Clip [t_min, t_max] to the grid rectangle.
  double t_lo = t_min, t_hi = t_max;
  const auto clip = [&](double origin, double dir, double lo, double hi) {
    if (dir == 0) return origin >= lo && origin <= hi;
    double ta = (lo - origin) / dir, tb = (hi - origin) / dir;
    if (ta > tb) std::swap(ta, tb);
    if (ta > t_lo) t_lo = ta;
    if (tb < t_hi) t_hi = tb;
    return t_lo <= t_hi;
  };
  if (!clip(o.x(), d.x(), grid_x0_, x1) || !clip(o.y(), d.y(), grid_y0_, y1)) return;

  const double px = o.x() + t_lo * d.x(), py = o.y() + t_lo * d.y();
  int ix = static_cast<int>((px - grid_x0_) / cell_size_);
  int iy = static_cast<int>((py - grid_y0_) / cell_size_);
  ix = ix < 0 ? 0 : (ix >= grid_nx_ ? grid_nx_ - 1 : ix);
  iy = iy < 0 ? 0 : (iy >= grid_ny_ ? grid_ny_ - 1 : iy);
  const int step_x = d.x() > 0 ? 1 : (d.x() < 0 ? -1 : 0);
  const int step_y = d.y() > 0 ? 1 : (d.y() < 0 ? -1 : 0);
  double t_next_x = kInfinity, t_next_y = kInfinity, dt_x = kInfinity, dt_y = kInfinity;
  if (step_x != 0) {
    t_next_x = (grid_x0_ + (ix + (step_x > 0 ? 1 : 0)) * cell_size_ - o.x()) / d.x();
    dt_x = cell_size_ / std::abs(d.x());
  }
  if (step_y != 0) {
    t_next_y = (grid_y0_ + (iy + (step_y > 0 ? 1 : 0)) * cell_size_ - o.y()) / d.y();
    dt_y = cell_size_ / std::abs(d.y());
  }
  while (true) {
    const double t_cell_exit = std::min(std::min(t_next_x, t_next_y), t_hi);
    const int cell = iy * grid_nx_ + ix;
    if (!visit_cell(cell_start_[cell], cell_start_[cell + 1], t_cell_exit)) return;
    if (t_cell_exit >= t_hi) return;
    if (t_next_x < t_next_y) {
      ix += step_x;
      if (ix < 0 || ix >= grid_nx_) return;
      t_next_x += dt_x;
    } else {
      iy += step_y;
      if (iy < 0 || iy >= grid_ny_) return;
      t_next_y += dt_y;
    }
  }
}

template <typename Visit>
void SceneGeometry::forEachSolidAlong(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_min,
                                      double t_max, Visit&& visit) const {
  traverseCells(o, d, t_min, t_max, [&](int first, int last, double) {
    for (int i = first; i < last; ++i) {
      if (!visit(cell_items_[i])) return false;
    }
    return true;
  });
}

}  // namespace beft::camera
