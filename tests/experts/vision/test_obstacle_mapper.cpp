// Vision expert logic, part 2: the obstacle map M_O from depth images.
#include <gtest/gtest.h>

#include <cmath>

#include "lib/camera/camera_messages.hpp"
#include "lib/scene/camera_model.hpp"
#include "experts/vision/depth_rays.hpp"
#include "lib/wire/obstacle_map_codec.hpp"
#include "experts/vision/obstacle_mapper.hpp"
#include "lib/scene/ray_caster.hpp"
#include "tests/experts/support/scene_builders.hpp"
#include "lib/scene/scene_geometry.hpp"

using namespace beft;

namespace {

constexpr uint8_t kUnknown = obstacle_map_t::CELL_UNKNOWN;
constexpr uint8_t kFree = obstacle_map_t::CELL_FREE;
constexpr uint8_t kOccupied = obstacle_map_t::CELL_OCCUPIED;

// A depth image from a camera at (2, 5, 1.6) looking along +x (tilted by
// pitch_deg) at a wall whose face is the plane x = wall_x (2.5 m tall, across
// the whole world), over flat ground; computed from the camera model's pixel
// rays.
camera_frame_t wallDepthImage(double wall_x, double pitch_deg = 0) {
  camera::Camera cam;
  cam.pose = {2, 5, 1.6, 0, pitch_deg};
  cam.intrinsics = {60, 160, 120, 20};  // 3.6 cm per pixel at the wall: every 10 cm cell is hit
  camera_frame_t f{};
  f.encoding = camera_frame_t::ENCODING_DEPTH_MM16;
  f.width = cam.intrinsics.width;
  f.height = cam.intrinsics.height;
  f.fov = cam.intrinsics.fov_deg;
  f.range = cam.intrinsics.range;
  f.cam_x = cam.pose.x;
  f.cam_y = cam.pose.y;
  f.cam_z = cam.pose.z;
  f.cam_yaw = cam.pose.yaw_deg;
  f.cam_pitch = cam.pose.pitch_deg;
  for (int v = 0; v < f.height; ++v) {
    for (int u = 0; u < f.width; ++u) {
      const Eigen::Vector3d d = camera::pixelRay(cam, u, v);  // forward component 1: t is the z-depth
      const double t_wall = (wall_x - cam.pose.x) / d.x();  // along the ray: z-depth
      const double z_wall = cam.pose.z + t_wall * d.z();
      double depth = 0;
      if (z_wall >= 0 && z_wall <= 2.5) depth = t_wall;
      else if (d.z() < 0) depth = -cam.pose.z / d.z();  // ground before the wall
      const auto mm = static_cast<uint16_t>(std::lround(depth * 1000));
      f.data.push_back(static_cast<uint8_t>(mm & 0xff));
      f.data.push_back(static_cast<uint8_t>(mm >> 8));
    }
  }
  f.data_size = static_cast<int32_t>(f.data.size());
  return f;
}

// Hand-made rays as a one-row image: each ray is its own image column.
vision::DepthImage oneRow(const std::vector<vision::DepthRay>& rays) {
  return {static_cast<int>(rays.size()), 1, rays};
}

}  // namespace

TEST(ObstacleMapper, WallAtKnownDistanceMarksItsCellsAndTheFreeSpaceBeforeIt) {
  vision::ObstacleMapper map(30, 10, {});
  ASSERT_EQ(map.width(), 300);
  ASSERT_EQ(map.height(), 100);
  const camera_frame_t depth = wallDepthImage(7.05);  // the middle of column 70
  map.integrate({depth.cam_x, depth.cam_y, depth.cam_z}, vision::depthRays(depth));

  // The wall is seen for |y - 5| <= 5.05 tan(30 deg) = 2.9 m: rows 22..78.
  for (int row = 25; row <= 75; ++row) EXPECT_EQ(map.cell(70, row), kOccupied) << "row " << row;
  EXPECT_EQ(map.cell(70, 10), kUnknown);  // outside the field of view
  // Only column 70 holds obstacles.
  int occupied_outside = 0;
  for (int row = 0; row < map.height(); ++row)
    for (int column = 0; column < map.width(); ++column)
      if (column != 70 && map.cell(column, row) == kOccupied) ++occupied_outside;
  EXPECT_EQ(occupied_outside, 0);
  EXPECT_GE(map.countCells(kOccupied), 50);
  // Free space between the camera and the wall, along the optical axis.
  for (int column = 21; column <= 69; ++column) EXPECT_EQ(map.cell(column, 50), kFree) << "column " << column;
  EXPECT_EQ(map.cell(72, 50), kUnknown);  // behind the wall
  EXPECT_EQ(map.cell(10, 50), kUnknown);  // behind the camera
  EXPECT_EQ(map.cellAt(7.05, 5.0), kOccupied);
}

TEST(ObstacleMapper, ATiltedCameraMapsTheSameWall) {
  // Looking 10 deg down: the rays of an image column fan out horizontally,
  // so the mapper traces them one by one.
  vision::ObstacleMapper map(30, 10, {});
  const camera_frame_t depth = wallDepthImage(7.05, -10);
  const vision::DepthImage image = vision::depthRays(depth);
  EXPECT_FALSE(image.level);
  EXPECT_TRUE(vision::depthRays(wallDepthImage(7.05)).level);
  map.integrate({depth.cam_x, depth.cam_y, depth.cam_z}, image);
  for (int row = 25; row <= 75; ++row) EXPECT_EQ(map.cell(70, row), kOccupied) << "row " << row;
  int occupied_outside = 0;
  for (int row = 0; row < map.height(); ++row)
    for (int column = 0; column < map.width(); ++column)
      if (column != 70 && map.cell(column, row) == kOccupied) ++occupied_outside;
  EXPECT_EQ(occupied_outside, 0);
  for (int column = 30; column <= 69; ++column) EXPECT_EQ(map.cell(column, 50), kFree) << "column " << column;
  EXPECT_EQ(map.cell(72, 50), kUnknown);
}

TEST(ObstacleMapper, ASecondViewNeverErasesTheWall) {
  vision::ObstacleMapper map(30, 10, {});
  const camera_frame_t depth = wallDepthImage(7.05);
  map.integrate({depth.cam_x, depth.cam_y, depth.cam_z}, vision::depthRays(depth));
  const int occupied = map.countCells(kOccupied);
  // Rays passing high over the wall's cells towards a farther ground point.
  const Eigen::Vector3d origin(2.05, 5.05, 1.6);
  std::vector<vision::DepthRay> over_the_top;
  for (double y : {4.05, 5.05, 6.05}) {
    const Eigen::Vector3d target(12.05, y, 0.0);
    over_the_top.push_back({target - origin, 1.0});
  }
  map.integrate(origin, oneRow(over_the_top));
  EXPECT_EQ(map.countCells(kOccupied), occupied);
}

TEST(ObstacleMapper, AnObstacleThatLeftIsClearedOnlyWhenItsFloorIsSeen) {
  vision::ObstacleMapper map(10, 10, {});
  const Eigen::Vector3d origin(2.05, 5.05, 1.6);
  auto rayTo = [&](const Eigen::Vector3d& point) { return vision::DepthRay{point - origin, 1.0}; };

  // A person at x = 5.05 is seen: cell (50, 50) becomes occupied.
  map.integrate(origin, oneRow({rayTo({5.05, 5.05, 1.0})}));
  ASSERT_EQ(map.cell(50, 50), kOccupied);

  // Same frame evidence never clears: an obstacle return and a low ray through its cell.
  map.integrate(origin, oneRow({rayTo({5.05, 5.05, 1.0}), rayTo({5.25, 5.05, 0.0})}));
  EXPECT_EQ(map.cell(50, 50), kOccupied);

  // The person walked away; a ray to the ground just behind crosses the cell
  // above 0.15 m: no proof the cell is empty at floor level.
  map.integrate(origin, oneRow({rayTo({5.55, 5.05, 0.0})}));
  EXPECT_EQ(map.cell(50, 50), kOccupied);

  // A ray to the ground at x = 5.25 crosses cell 50 below 0.15 m: cleared.
  map.integrate(origin, oneRow({rayTo({5.25, 5.05, 0.0})}));
  EXPECT_EQ(map.cell(50, 50), kFree);
  EXPECT_EQ(map.cell(52, 50), kFree);  // the ground return's own cell is seen too
}

TEST(ObstacleMapper, APersonWhoWalkedAwayLeavesNoTraceButTheWallStays) {
  // Rendered frames: the camera at (2, 5) looks along +x at a person 4 m
  // ahead and a wall 8 m ahead; then the person steps 3 m aside.
  camera::Camera cam;
  cam.pose = {2, 5, 1.6, 0, 0};
  auto depthFrame = [&](double person_y) {
    const auto s = test::scene({test::cylinderObject("walker", "person", 6, person_y, 0.3, 1.8),
                                test::boxObject("wall", "wall", 10, 5, 90, 8, 0.2, 2.5)},
                               0, 20, 10);
    camera::CameraMessages messages;
    camera::encodeCameraMessages(camera::renderFrame(camera::SceneGeometry::fromMessage(s), cam), 0, 0,
                                 {"walker", "wall"}, messages);
    return messages.depth;
  };
  auto occupiedNear = [](const vision::ObstacleMapper& map, double x, double y, double half) {
    int count = 0;
    for (double cx = x - half; cx <= x + half; cx += 0.1)
      for (double cy = y - half; cy <= y + half; cy += 0.1) count += map.cellAt(cx, cy) == kOccupied;
    return count;
  };
  vision::ObstacleMapper map(20, 10, {});
  map.integrate({2, 5, 1.6}, vision::depthRays(depthFrame(5)));
  EXPECT_GT(occupiedNear(map, 6, 5, 0.4), 0);
  const int wall_before = occupiedNear(map, 9.9, 5, 2.5);
  EXPECT_GT(wall_before, 20);

  map.integrate({2, 5, 1.6}, vision::depthRays(depthFrame(8)));
  EXPECT_EQ(occupiedNear(map, 6, 5, 0.4), 0);  // the floor where it stood is seen again
  EXPECT_GT(occupiedNear(map, 6, 8, 0.4), 0);  // where it is now
  EXPECT_GE(occupiedNear(map, 9.9, 5, 2.5), wall_before);
}

TEST(ObstacleMapper, LowReturnsAndNoReturnsAreNotObstacles) {
  vision::ObstacleMapper map(10, 10, {});
  const Eigen::Vector3d origin(2.05, 5.05, 1.6);
  map.integrate(origin, oneRow({{Eigen::Vector3d(5.05, 5.05, 0.1) - origin, 1.0},  // 0.1 m: below the threshold
                                {Eigen::Vector3d(1, 0, 0), 0.0}}));                 // no return
  EXPECT_EQ(map.countCells(kOccupied), 0);
  EXPECT_EQ(map.cell(70, 50), kUnknown);  // the no-return ray marks nothing
  EXPECT_EQ(map.cell(40, 50), kFree);
}

TEST(ObstacleMapper, MessageOfAThirtyByTwentyWorldDecodesAndStaysUnder64KB) {
  vision::ObstacleMapper map(30, 20, {});
  const camera_frame_t depth = wallDepthImage(7.05);
  map.integrate({depth.cam_x, depth.cam_y, depth.cam_z}, vision::depthRays(depth));
  const obstacle_map_t message = map.toMessage(1234, 5);
  EXPECT_EQ(message.width, 300);
  EXPECT_EQ(message.height, 200);
  EXPECT_EQ(message.tick, 5);
  EXPECT_EQ(message.encoding, obstacle_map_t::ENCODING_RLE_ZSTD);
  EXPECT_LT(message.getEncodedSize(), 64 * 1024);
  const auto decoded = planners::decodeObstacleMap(message);
  EXPECT_EQ(decoded.cells, map.cells());
  EXPECT_DOUBLE_EQ(decoded.resolution, 0.1);
}

TEST(ObstacleMapper, RefusesABadGridOrImage) {
  vision::ObstacleMapper map(10, 10, {});
  EXPECT_THROW(map.integrate({1, 1, 1.6}, vision::DepthImage{3, 2, {}}), std::invalid_argument);
  EXPECT_THROW(vision::ObstacleMapper(0, 10, {}), std::invalid_argument);
  vision::ObstacleMapConfig config;
  config.resolution = -1;
  EXPECT_THROW(vision::ObstacleMapper(10, 10, config), std::invalid_argument);
}

TEST(ObstacleMapper, FrameRaysGiveTheMapOfTheStoredRays) {
  // Level and tilted frames, one after the other, so clearing is exercised too.
  const camera_frame_t frames[] = {wallDepthImage(7.05), wallDepthImage(6.35, -12), wallDepthImage(9.25),
                                   wallDepthImage(5.15, 8)};
  vision::ObstacleMapper from_stored(30, 10, {}), from_frame(30, 10, {});
  for (const camera_frame_t& depth : frames) {
    from_stored.integrate({depth.cam_x, depth.cam_y, depth.cam_z}, vision::depthRays(depth));
    from_frame.integrate(vision::DepthFrameRays(depth));
    EXPECT_EQ(from_frame.cells(), from_stored.cells()) << "wall frame with pitch " << depth.cam_pitch;
    EXPECT_EQ(from_frame.version(), from_stored.version());
  }
  EXPECT_GT(from_frame.countCells(kOccupied), 0);
  EXPECT_GT(from_frame.countCells(kFree), 0);
}

TEST(ObstacleMapper, FrameRaysRefuseAFrameThatIsNotDepth) {
  camera_frame_t colour = wallDepthImage(7.05);
  colour.encoding = camera_frame_t::ENCODING_RGB8;
  EXPECT_THROW(vision::DepthFrameRays{colour}, std::invalid_argument);
  camera_frame_t short_frame = wallDepthImage(7.05);
  short_frame.data.pop_back();
  EXPECT_THROW(vision::DepthFrameRays{short_frame}, std::invalid_argument);
}
