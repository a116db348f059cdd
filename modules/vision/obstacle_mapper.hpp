// The obstacle map M_O (paper section 3.1): footprints of every obstacle the
// camera has seen so far, accumulated over the run from depth images.
//
// Per frame, each depth pixel is a ray from the camera with the range of its
// return (none within the sensor range: no evidence at all):
//  - a return higher than obstacle_min_height above the ground is a point of
//    an obstacle: its cell becomes OCCUPIED;
//  - the cells the ray crossed before its return become FREE if they were
//    UNKNOWN (the ray saw through them);
//  - an OCCUPIED cell is cleared to FREE only when a ray crossed it entirely
//    below obstacle_min_height: whatever stood there is gone. This is how a
//    person who walked away stops blocking the map once the floor where they
//    stood is seen again, while a ray passing high over a low obstacle (or a
//    view of a wall from another side) never erases it. Cells hit in the same
//    frame are never cleared by that frame.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <beft/obstacle_map_t.hpp>

namespace beft::vision {

// One depth pixel: the return is at origin + t * direction (direction need
// not be unit length: camera::pixelRay has forward component 1, so t is the
// z-depth). t <= 0: no return within the sensor range.
struct DepthRay {
  Eigen::Vector3d direction;  // world frame
  double t = 0;
};

struct ObstacleMapConfig {
  double resolution = 0.1;           // cell edge [m]
  double obstacle_min_height = 0.15; // returns above this are obstacles [m]
};

class ObstacleMapper {
 public:
  // A grid covering x in [0, world_width], y in [0, world_height].
  ObstacleMapper(double world_width, double world_height, const ObstacleMapConfig& config);

  // Adds one frame seen from camera position origin. free_space_stride: use
  // every n-th ray for free space (all rays always mark obstacles).
  void integrate(const Eigen::Vector3d& origin, const std::vector<DepthRay>& rays, int free_space_stride = 1);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return config_.resolution; }
  // CELL_* value of cell (column, row); UNKNOWN outside the grid.
  uint8_t cell(int column, int row) const;
  // CELL_* value of the cell holding world point (x, y).
  uint8_t cellAt(double x, double y) const;
  int countCells(uint8_t value) const;
  const std::vector<uint8_t>& cells() const { return cells_; }

  // The whole map as a message (RLE, or raw when that is smaller).
  obstacle_map_t toMessage(int64_t utime, int64_t tick) const;

 private:
  bool cellOf(double x, double y, int& column, int& row) const;
  void traverseFreeSpace(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_return);

  ObstacleMapConfig config_;
  int width_ = 0;
  int height_ = 0;
  std::vector<uint8_t> cells_;
  std::vector<uint32_t> hit_in_frame_;  // frame number of the last obstacle return per cell
  uint32_t frame_ = 0;
};

}  // namespace beft::vision
