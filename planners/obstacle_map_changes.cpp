#include "obstacle_map_changes.hpp"

#include <algorithm>
#include <string>

namespace beft::planners {

void CellRect::include(int x, int y) {
  if (empty()) {
    x0 = x;
    y0 = y;
    width = height = 1;
    return;
  }
  const int x1 = std::max(x0 + width, x + 1), y1 = std::max(y0 + height, y + 1);
  x0 = std::min(x0, x);
  y0 = std::min(y0, y);
  width = x1 - x0;
  height = y1 - y0;
}

namespace {

bool fits(const CellRect& rect, int map_width, int map_height) {
  return rect.x0 >= 0 && rect.y0 >= 0 && rect.width >= 0 && rect.height >= 0 &&
         static_cast<int64_t>(rect.x0) + rect.width <= map_width &&
         static_cast<int64_t>(rect.y0) + rect.height <= map_height;
}

}  // namespace

beft::obstacle_map_changes_t makeMapChanges(const std::vector<uint8_t>& cells, int map_width, int map_height,
                                            const CellRect& rect, int64_t keyframe_tick, int64_t utime,
                                            int64_t tick) {
  if (!fits(rect, map_width, map_height) || cells.size() != static_cast<size_t>(map_width) * map_height)
    throw ObstacleMapError("changed rectangle leaves the map");
  beft::obstacle_map_changes_t changes{};
  changes.utime = utime;
  changes.tick = tick;
  changes.keyframe_tick = keyframe_tick;
  changes.encoding = beft::obstacle_map_t::ENCODING_RLE_ZSTD;
  if (!rect.empty()) {
    ObstacleCells part;
    part.width = rect.width;
    part.height = rect.height;
    part.cells.reserve(static_cast<size_t>(rect.width) * rect.height);
    for (int y = rect.y0; y < rect.y0 + rect.height; ++y) {
      const auto row = cells.begin() + static_cast<size_t>(y) * map_width + rect.x0;
      part.cells.insert(part.cells.end(), row, row + rect.width);
    }
    changes.x0 = rect.x0;
    changes.y0 = rect.y0;
    changes.width = rect.width;
    changes.height = rect.height;
    changes.data = makeObstacleMap(part, changes.encoding).data;
  }
  changes.data_size = static_cast<int32_t>(changes.data.size());
  return changes;
}

void applyMapChanges(const beft::obstacle_map_changes_t& changes, ObstacleCells& map) {
  const CellRect rect{changes.x0, changes.y0, changes.width, changes.height};
  if (!fits(rect, map.width, map.height))
    throw ObstacleMapError("changed rectangle (" + std::to_string(changes.x0) + ", " + std::to_string(changes.y0) +
                           ") " + std::to_string(changes.width) + " x " + std::to_string(changes.height) +
                           " does not fit the " + std::to_string(map.width) + " x " + std::to_string(map.height) +
                           " map");
  if (rect.empty()) return;
  // Decoded as a map of the rectangle's size: the same checks and size guard.
  beft::obstacle_map_t part_message{};
  part_message.width = rect.width;
  part_message.height = rect.height;
  part_message.resolution = map.resolution;
  part_message.encoding = changes.encoding;
  part_message.data_size = changes.data_size;
  part_message.data = changes.data;
  const ObstacleCells part = decodeObstacleMap(part_message);
  for (int y = 0; y < rect.height; ++y)
    std::copy_n(part.cells.begin() + static_cast<size_t>(y) * rect.width, rect.width,
                map.cells.begin() + static_cast<size_t>(rect.y0 + y) * map.width + rect.x0);
}

std::shared_ptr<const ObstacleCells> ObstacleMapAssembler::mapOf(const beft::obstacle_map_t& keyframe,
                                                                 const beft::obstacle_map_changes_t* changes) {
  if (changes != nullptr && changes->keyframe_tick != keyframe.tick)
    throw ObstacleMapError("changes of tick " + std::to_string(changes->tick) + " belong to the keyframe of tick " +
                           std::to_string(changes->keyframe_tick) + ", not " + std::to_string(keyframe.tick));
  if (!keyframe_cells_ || keyframe_.tick != keyframe.tick || !sameEncodedMap(keyframe_, keyframe)) {
    keyframe_cells_ = std::make_shared<const ObstacleCells>(decodeObstacleMap(keyframe));
    keyframe_ = keyframe;
  }
  if (changes == nullptr || changes->width <= 0 || changes->height <= 0) return keyframe_cells_;
  auto assembled = std::make_shared<ObstacleCells>(*keyframe_cells_);
  applyMapChanges(*changes, *assembled);
  return assembled;
}

}  // namespace beft::planners
