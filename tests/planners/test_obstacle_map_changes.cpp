// A keyframe and the rectangle changed since it make the map of a tick; a
// rectangle that does not fit, damaged data or another keyframe's changes are
// refused with what is wrong, the map untouched.
#include <gtest/gtest.h>

#include <random>

#include "obstacle_map_changes.hpp"

namespace bp = beft::planners;
using beft::obstacle_map_t;

namespace {
bp::ObstacleCells emptyMap(int width, int height) {
  bp::ObstacleCells map;
  map.width = width;
  map.height = height;
  map.cells.assign(static_cast<size_t>(width) * height, obstacle_map_t::CELL_UNKNOWN);
  return map;
}
}  // namespace

TEST(ObstacleMapChanges, TheRectangleChangedSinceTheKeyframeGivesEveryTicksMap) {
  std::mt19937 random(3);
  bp::ObstacleCells map = emptyMap(120, 80);
  const obstacle_map_t keyframe = bp::makeObstacleMap(map, obstacle_map_t::ENCODING_RLE_ZSTD, 0, 0);
  bp::CellRect changed;
  bp::ObstacleMapAssembler assembler;
  for (int tick = 1; tick <= 30; ++tick) {
    // A robot's view: a few cells near a point that wanders.
    const int cx = 20 + 2 * tick, cy = 30 + tick % 7;
    for (int i = 0; i < 40; ++i) {
      const int x = cx + static_cast<int>(random() % 9) - 4, y = cy + static_cast<int>(random() % 9) - 4;
      map.cells[static_cast<size_t>(y) * map.width + x] = 1 + random() % 2;
      changed.include(x, y);
    }
    const auto changes = bp::makeMapChanges(map.cells, map.width, map.height, changed, 0, tick * 100000, tick);
    EXPECT_EQ(changes.keyframe_tick, 0);
    EXPECT_LT(changes.data_size, 2000) << "only the rectangle travels";
    const auto made = assembler.mapOf(keyframe, &changes);
    ASSERT_EQ(made->cells, map.cells) << "tick " << tick;
  }
  EXPECT_EQ(assembler.mapOf(keyframe, nullptr)->cells, emptyMap(120, 80).cells);  // the keyframe's own tick
}

TEST(ObstacleMapChanges, RefusesWhatDoesNotFitOrDecodeAndLeavesTheMapAlone) {
  bp::ObstacleCells map = emptyMap(50, 40);
  map.cells[5 * 50 + 5] = obstacle_map_t::CELL_OCCUPIED;
  bp::CellRect rect;
  rect.include(4, 4);
  rect.include(6, 6);
  auto changes = bp::makeMapChanges(map.cells, map.width, map.height, rect, 10, 0, 12);
  bp::ObstacleCells target = emptyMap(50, 40);
  bp::applyMapChanges(changes, target);
  EXPECT_EQ(target.at(5, 5), obstacle_map_t::CELL_OCCUPIED);

  bp::ObstacleCells untouched = emptyMap(50, 40);
  auto outside = changes;
  outside.x0 = 48;  // 3 columns from 48 leave a 50-column map
  EXPECT_THROW(bp::applyMapChanges(outside, untouched), bp::ObstacleMapError);
  auto negative = changes;
  negative.y0 = -1;
  EXPECT_THROW(bp::applyMapChanges(negative, untouched), bp::ObstacleMapError);
  auto damaged = changes;
  damaged.data[damaged.data.size() / 2] ^= 0x5a;
  EXPECT_THROW(bp::applyMapChanges(damaged, untouched), bp::ObstacleMapError);
  auto too_big = changes;
  too_big.width = 40;  // says 40 x 3 cells, holds 9
  EXPECT_THROW(bp::applyMapChanges(too_big, untouched), bp::ObstacleMapError);
  EXPECT_EQ(untouched.cells, emptyMap(50, 40).cells);

  bp::CellRect outside_rect;
  outside_rect.include(49, 39);
  outside_rect.width = 2;
  EXPECT_THROW(bp::makeMapChanges(map.cells, map.width, map.height, outside_rect, 0, 0, 1), bp::ObstacleMapError);

  const obstacle_map_t other_keyframe = bp::makeObstacleMap(emptyMap(50, 40), obstacle_map_t::ENCODING_RLE, 0, 20);
  EXPECT_THROW(bp::ObstacleMapAssembler().mapOf(other_keyframe, &changes), bp::ObstacleMapError);
}
