// A keyframe and the rectangle changed since it make the map of a tick; a
// rectangle that does not fit, damaged data or another keyframe's changes are
// refused with what is wrong, the map untouched.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "lib/wire/obstacle_map_changes.hpp"

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

// Maps let go of are brought up to date in place; a map still held is never
// written again; lastChangedCells says whether the cells differ from the map
// returned before, over keyframes, ticks without change, rectangles that
// move and changes refused on the way.
TEST(ObstacleMapChanges, ReusesOnlyMapsNobodyHoldsAndTellsWhetherCellsChanged) {
  std::mt19937 random(5);
  bp::ObstacleCells truth = emptyMap(60, 40);
  bp::ObstacleMapAssembler assembler;
  obstacle_map_t keyframe;
  bp::CellRect changed;
  std::vector<std::pair<std::shared_ptr<const bp::ObstacleCells>, std::vector<uint8_t>>> held;
  std::shared_ptr<const bp::ObstacleCells> newest;
  std::vector<uint8_t> returned_before;
  std::weak_ptr<const bp::ObstacleCells> before_last, last;  // not holding them
  int reused = 0, unchanged_ticks = 0, refused = 0, earlier_asked = 0;
  std::vector<std::pair<beft::obstacle_map_changes_t, std::vector<uint8_t>>> history;  // this keyframe's ticks
  for (int tick = 0; tick < 300; ++tick) {
    if (tick % 25 == 0) {
      keyframe = bp::makeObstacleMap(truth, obstacle_map_t::ENCODING_RLE_ZSTD, 0, tick);
      changed = bp::CellRect{};
    } else if (random() % 3 != 0) {
      // A few cells somewhere; now and then the same value again (no change).
      const int cx = static_cast<int>(random() % 56) + 2, cy = static_cast<int>(random() % 36) + 2;
      for (int i = 0; i < 6; ++i) {
        const int x = cx + static_cast<int>(random() % 5) - 2, y = cy + static_cast<int>(random() % 5) - 2;
        truth.cells[static_cast<size_t>(y) * truth.width + x] = random() % 4 == 0 ? 0 : 1 + random() % 2;
        changed.include(x, y);
      }
    }
    const auto changes = bp::makeMapChanges(truth.cells, truth.width, truth.height, changed, keyframe.tick, 0, tick);
    if (tick % 17 == 5 && !changed.empty()) {
      auto damaged = changes;
      damaged.data[damaged.data.size() / 2] ^= 0x5a;
      EXPECT_THROW(assembler.mapOf(keyframe, &damaged), bp::ObstacleMapError);
      ++refused;
    }
    newest = assembler.mapOf(keyframe, changed.empty() ? nullptr : &changes);
    ASSERT_EQ(newest->cells, truth.cells) << "tick " << tick;
    const bool differs = returned_before.empty() || returned_before != truth.cells;
    EXPECT_EQ(assembler.lastChangedCells(), differs) << "tick " << tick;
    unchanged_ticks += !differs;
    returned_before = truth.cells;
    // The map of two calls ago, let go of meanwhile, is the one returned now.
    reused += !changed.empty() && before_last.lock() == newest && last.lock() != newest;
    before_last = last;
    last = newest;
    // Now and then the map of an earlier tick of this keyframe again (a
    // reader catching up): its rectangle is smaller than the one written.
    if (tick % 25 == 0) history.clear();
    history.emplace_back(changes, truth.cells);
    if (tick % 9 == 4 && history.size() > 3) {
      const auto& [earlier_changes, earlier_cells] = history[random() % (history.size() - 2)];
      const auto earlier = assembler.mapOf(keyframe, earlier_changes.width > 0 ? &earlier_changes : nullptr);
      ASSERT_EQ(earlier->cells, earlier_cells) << "tick " << tick << ", an earlier one";
      EXPECT_EQ(assembler.lastChangedCells(), earlier_cells != returned_before);
      returned_before = earlier_cells;
      ++earlier_asked;
      newest = earlier;
      before_last = last;
      last = newest;
    }
    if (random() % 7 == 0) held.emplace_back(newest, returned_before);  // a reader that keeps it
  }
  for (const auto& [map, cells] : held) EXPECT_EQ(map->cells, cells) << "a held map was written";
  EXPECT_GT(reused, 100) << "maps let go are brought up to date, not made anew";
  EXPECT_GT(unchanged_ticks, 50);
  EXPECT_GT(refused, 5);
  EXPECT_GT(earlier_asked, 20);
}
