// The obstacle map of a tick as a keyframe (OBSTACLE_MAP) and the rectangle
// of cells changed since it (OBSTACLE_MAP_CHANGES, obstacle_map_changes_t):
// the one place that says how the two make the map, for the vision expert
// that writes them and every process and tool that reads them.
#pragma once

#include <beft/obstacle_map_changes_t.hpp>
#include <beft/obstacle_map_t.hpp>

#include <cstdint>
#include <memory>
#include <vector>

#include "lib/wire/obstacle_map_codec.hpp"

namespace beft::planners {

// A rectangle of cells; empty when width or height is 0.
struct CellRect {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
  void include(int x, int y);  // grows to hold cell (x, y)
};

// The cells of `rect` of a map (`cells`, row by row, map_width x
// map_height), RLE_ZSTD, as the changes of tick `tick` since the keyframe of
// `keyframe_tick`. Throws ObstacleMapError if rect leaves the map.
beft::obstacle_map_changes_t makeMapChanges(const std::vector<uint8_t>& cells, int map_width, int map_height,
                                            const CellRect& rect, int64_t keyframe_tick, int64_t utime,
                                            int64_t tick);

// Writes the changes' rectangle over `map` (the keyframe's map, or the same
// keyframe's map of an earlier tick: the rectangle only grows). Throws
// ObstacleMapError if the rectangle does not fit the map or its data does not
// decode to its cells; `map` is then untouched.
void applyMapChanges(const beft::obstacle_map_changes_t& changes, ObstacleCells& map);

// The map of a tick from its keyframe and changes (null: the keyframe's own
// tick), decoding each keyframe once. Throws ObstacleMapError if the changes
// belong to another keyframe or do not apply.
//
// A map it returned is never written again while anyone else holds it. One
// nobody holds any more (a reader keeps the newest and lets go of the one
// before) is brought up to date in place: its old rectangle back to the
// keyframe, the new one written, instead of copying the whole keyframe (two
// million cells in a 160 x 120 m world) at every tick the map changes.
class ObstacleMapAssembler {
 public:
  std::shared_ptr<const ObstacleCells> mapOf(const beft::obstacle_map_t& keyframe,
                                             const beft::obstacle_map_changes_t* changes);
  // Whether the map mapOf last returned has other cells (or another size,
  // resolution or origin) than the one it returned before; true the first time.
  bool lastChangedCells() const { return last_changed_cells_; }

 private:
  // A map made here: the keyframe (by tick) with `rect` written over it.
  struct Made {
    std::shared_ptr<ObstacleCells> cells;
    int64_t keyframe_tick = -1;
    CellRect rect;
  };
  static constexpr std::size_t kKeptMaps = 2;

  Made& freeMapFor(int64_t keyframe_tick);
  void noteReturned(const std::shared_ptr<const ObstacleCells>& map, const CellRect& rect);

  std::shared_ptr<const ObstacleCells> keyframe_cells_;
  beft::obstacle_map_t keyframe_;  // the one decoded, to know it again
  uint64_t keyframe_generation_ = 0;  // grows with every keyframe decoded
  std::vector<Made> made_;            // at most kKeptMaps
  // The map last returned and what it was made of, to tell what changed.
  std::shared_ptr<const ObstacleCells> last_;
  uint64_t last_generation_ = 0;
  CellRect last_rect_;
  bool last_changed_cells_ = true;
};

}  // namespace beft::planners
