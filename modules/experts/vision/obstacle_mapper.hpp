// The obstacle map M_O (paper section 3.1): footprints of every obstacle the
// camera has seen so far, accumulated over the run from depth images.
//
// Per frame, each depth pixel is a ray from the camera with the ray parameter
// of its return (none within the sensor range: no evidence at all):
//  - a return higher than obstacle_min_height above the ground is a point of
//    an obstacle: its cell becomes OCCUPIED;
//  - cells a ray crossed before its return were seen: UNKNOWN becomes FREE.
//    Traced along the farthest-reaching ray of each image column, which
//    crosses every cell the column's other rays cross when the camera is level
//    (the rays of a column share one horizontal direction then; with the head
//    tilted they fan out slightly and a few cells between them stay UNKNOWN);
//  - an OCCUPIED cell is cleared to FREE only when a ray crossed it entirely
//    below obstacle_min_height (the last stretch of a ray to the floor): what
//    stood there is gone. Each cell is checked against the lowest floor ray of
//    the column over it (the one whose return is nearest beyond it): for a
//    level camera in one walk along the column, for a tilted one ray by ray.
//    The camera is assumed above obstacle_min_height. So a person who walked away stops blocking the map
//    once the floor where they stood is seen again, while a ray passing high
//    over a low obstacle, or a view of a wall from another side, never erases
//    it. Cells hit in the same frame are never cleared by that frame.
#pragma once

#include <unordered_set>

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <beft/obstacle_map_changes_t.hpp>
#include <beft/obstacle_map_t.hpp>

#include "lib/wire/obstacle_map_changes.hpp"

namespace beft::vision {

// One depth pixel: the return is at origin + t * direction (direction need
// not be unit length: camera::pixelRay has forward component 1, so t is the
// z-depth). t <= 0: no return within the sensor range.
struct DepthRay {
  Eigen::Vector3d direction;  // world frame
  double t = 0;
};

// The rays of one depth image, row-major: ray (u, v) is rays[v * width + u].
struct DepthImage {
  int width = 0, height = 0;
  std::vector<DepthRay> rays;
  // Taken with a level camera (no pitch, no roll): the rays of an image
  // column share one horizontal direction.
  bool level = false;
};

class DepthFrameRays;  // depth_rays.hpp

struct ObstacleMapConfig {
  double resolution = 0.1;           // cell edge [m]
  double obstacle_min_height = 0.15; // returns above this are obstacles [m]
};

class ObstacleMapper {
 public:
  // A grid covering x in [0, world_width], y in [0, world_height].
  ObstacleMapper(double world_width, double world_height, const ObstacleMapConfig& config);

  // Adds one frame seen from camera position origin. Throws
  // std::invalid_argument if the image's size does not match its rays.
  void integrate(const Eigen::Vector3d& origin, const DepthImage& image);
  // The same for a depth frame's rays, computed pixel by pixel on the way
  // (the same map as integrating depthRays(frame) from the frame's camera).
  void integrate(const DepthFrameRays& rays);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return config_.resolution; }
  // CELL_* value of cell (column, row); UNKNOWN outside the grid.
  uint8_t cell(int column, int row) const;
  // CELL_* value of the cell holding world point (x, y).
  uint8_t cellAt(double x, double y) const;
  int countCells(uint8_t value) const;
  const std::vector<uint8_t>& cells() const { return cells_; }
  // Grows whenever a cell changes value: an unchanged version means an
  // unchanged map.
  uint64_t version() const { return version_; }

  // A contact felt by the platform (a bumper) at world point (x, y) while
  // moving towards heading [deg]: the cells within radius of the segment of
  // `width` across the heading, centred on the point, become OCCUPIED and no
  // view clears them again (what was touched may be too low or too thin for
  // the camera to map).
  void markContact(double x, double y, double heading_deg, double width, double radius);
  std::size_t feltCells() const { return felt_.size(); }

  // Replaces every cell, e.g. with the map a previous run of the expert
  // published. Throws std::invalid_argument on a wrong count or value.
  void restoreCells(const std::vector<uint8_t>& cells);

  // The whole map as a message (RLE, or raw when that is smaller).
  obstacle_map_t toMessage(int64_t utime, int64_t tick) const;

  // The rectangle of every cell changed since the last markKeyframe() (the
  // map was then published whole), and those cells as a changes message.
  const planners::CellRect& changedSinceKeyframe() const { return changed_; }
  void markKeyframe() { changed_ = {}; }
  // After a restart from a keyframe and its changes: what had changed since.
  void restoreChanged(const planners::CellRect& changed) { changed_ = changed; }
  obstacle_map_changes_t changesMessage(int64_t keyframe_tick, int64_t utime, int64_t tick) const;

 private:
  bool cellOf(double x, double y, int& column, int& row) const;
  // Both integrate()s: ray_at(u, v) gives pixel (u, v)'s DepthRay; it is
  // asked bottom row first, each row left to right.
  template <typename RayAt>
  void integrateRays(const Eigen::Vector3d& origin, int width, int height, bool level, RayAt&& ray_at);
  // Walks the cells under o + t d for t in [t_begin, t_end) (Amanatides-Woo);
  // visit(index, t_enter, t_exit) for each, then ends at the cell of t_end
  // (not visited).
  template <typename Visit>
  void traverse(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_begin, double t_end,
                Visit&& visit) const;
  void set(std::size_t index, uint8_t value) {
    if (value != obstacle_map_t::CELL_OCCUPIED && !felt_.empty() && felt_.count(index) != 0) return;
    if (cells_[index] != value) {
      cells_[index] = value;
      ++version_;
      changed_.include(static_cast<int>(index % width_), static_cast<int>(index / width_));
    }
  }
  // A floor return of an image column: its ray is asked again by row when
  // needed (16 bytes here instead of the ray's 32).
  struct ColumnRay {
    double reach;  // horizontal distance to the return [m]
    int32_t v;     // image row
  };
  template <typename RayAt>
  void walkLevelColumn(const Eigen::Vector3d& origin, int u, const DepthRay& farthest, double reach,
                       const std::vector<ColumnRay>& floor_rays, RayAt& ray_at);
  template <typename RayAt>
  void traceColumnRays(const Eigen::Vector3d& origin, int u, const DepthRay& farthest,
                       const std::vector<ColumnRay>& floor_rays, RayAt& ray_at);
  void markSeen(const Eigen::Vector3d& origin, const DepthRay& ray);
  void markReturnCellSeen(const Eigen::Vector3d& origin, const DepthRay& ray);
  // From ray parameter t_from on (earlier cells were covered by a lower ray).
  void clearBelowThreshold(const Eigen::Vector3d& origin, const DepthRay& ray, double t_from);

  std::unordered_set<std::size_t> felt_;  // cells marked by contacts: never cleared
  ObstacleMapConfig config_;
  int width_ = 0;
  int height_ = 0;
  std::vector<uint8_t> cells_;
  // 1 for the cells with an obstacle return in the frame being integrated
  // (cleared again at its end through obstacle_cells_).
  std::vector<uint8_t> hit_this_frame_;
  uint64_t version_ = 0;
  planners::CellRect changed_;  // cells changed since the last keyframe
  // Scratch, kept between frames.
  struct ColumnScan {
    int farthest_v = -1;  // row of the farthest-reaching return, -1: none
    double farthest_reach = 0;
    std::vector<ColumnRay> floor_rays;
  };
  std::vector<ColumnScan> columns_;
  std::vector<std::size_t> obstacle_cells_;  // scratch, kept between frames
};

}  // namespace beft::vision
