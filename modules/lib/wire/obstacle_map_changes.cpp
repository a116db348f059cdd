#include "lib/wire/obstacle_map_changes.hpp"

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

namespace {

bool sameGrid(const ObstacleCells& a, const ObstacleCells& b) {
  return a.width == b.width && a.height == b.height && a.resolution == b.resolution && a.origin_x == b.origin_x &&
         a.origin_y == b.origin_y;
}

// The smallest rectangle holding both.
CellRect unite(const CellRect& a, const CellRect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  CellRect both = a;
  both.include(b.x0, b.y0);
  both.include(b.x0 + b.width - 1, b.y0 + b.height - 1);
  return both;
}

bool contains(const CellRect& outer, const CellRect& inner) {
  return inner.empty() || (!outer.empty() && inner.x0 >= outer.x0 && inner.y0 >= outer.y0 &&
                           inner.x0 + inner.width <= outer.x0 + outer.width &&
                           inner.y0 + inner.height <= outer.y0 + outer.height);
}

// Copies the rectangle's cells from one map to another of the same grid.
void copyRect(const ObstacleCells& from, const CellRect& rect, ObstacleCells& to) {
  for (int y = rect.y0; y < rect.y0 + rect.height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * from.width + rect.x0;
    std::copy_n(from.cells.begin() + row, rect.width, to.cells.begin() + row);
  }
}

bool sameInRect(const ObstacleCells& a, const ObstacleCells& b, const CellRect& rect) {
  for (int y = rect.y0; y < rect.y0 + rect.height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * a.width + rect.x0;
    if (!std::equal(a.cells.begin() + row, a.cells.begin() + row + rect.width, b.cells.begin() + row)) return false;
  }
  return true;
}

}  // namespace

ObstacleMapAssembler::Made& ObstacleMapAssembler::freeMapFor(int64_t keyframe_tick) {
  // Held only here, and not the map last returned (what the next one is told against).
  const auto free = [&](const Made& made) { return made.cells.use_count() == 1 && made.cells != last_; };
  Made* chosen = nullptr;
  for (Made& made : made_)
    if (free(made) && (chosen == nullptr || made.keyframe_tick == keyframe_tick)) chosen = &made;
  if (chosen == nullptr) {
    // Every kept map is held elsewhere: a new one, in place of the oldest.
    if (made_.size() >= kKeptMaps) made_.erase(made_.begin());
    made_.emplace_back();
    chosen = &made_.back();
  }
  if (!chosen->cells || chosen->keyframe_tick != keyframe_tick || !sameGrid(*chosen->cells, *keyframe_cells_)) {
    chosen->cells = std::make_shared<ObstacleCells>(*keyframe_cells_);
    chosen->keyframe_tick = keyframe_tick;
    chosen->rect = CellRect{};
  }
  return *chosen;
}

void ObstacleMapAssembler::noteReturned(const std::shared_ptr<const ObstacleCells>& map, const CellRect& rect) {
  if (!last_ || !sameGrid(*last_, *map)) {
    last_changed_cells_ = true;
  } else if (last_ == map) {
    last_changed_cells_ = false;
  } else if (last_generation_ == keyframe_generation_) {
    // Both are the same keyframe with a rectangle written: cells can only
    // differ where either rectangle lies.
    const CellRect both = unite(last_rect_, rect);
    last_changed_cells_ = !sameInRect(*last_, *map, both);
  } else {
    last_changed_cells_ = last_->cells != map->cells;
  }
  last_ = map;
  last_generation_ = keyframe_generation_;
  last_rect_ = rect;
}

std::shared_ptr<const ObstacleCells> ObstacleMapAssembler::mapOf(const beft::obstacle_map_t& keyframe,
                                                                 const beft::obstacle_map_changes_t* changes) {
  if (changes != nullptr && changes->keyframe_tick != keyframe.tick)
    throw ObstacleMapError("changes of tick " + std::to_string(changes->tick) + " belong to the keyframe of tick " +
                           std::to_string(changes->keyframe_tick) + ", not " + std::to_string(keyframe.tick));
  if (!keyframe_cells_ || keyframe_.tick != keyframe.tick || !sameEncodedMap(keyframe_, keyframe)) {
    keyframe_cells_ = std::make_shared<const ObstacleCells>(decodeObstacleMap(keyframe));
    keyframe_ = keyframe;
    ++keyframe_generation_;
    made_.clear();  // made of the keyframe before
  }
  if (changes == nullptr || changes->width <= 0 || changes->height <= 0) {
    noteReturned(keyframe_cells_, CellRect{});
    return keyframe_cells_;
  }
  Made& made = freeMapFor(keyframe.tick);
  const CellRect rect{changes->x0, changes->y0, changes->width, changes->height};
  // The old rectangle back to the keyframe where the new one does not cover it.
  if (!contains(rect, made.rect)) {
    copyRect(*keyframe_cells_, made.rect, *made.cells);
    made.rect = CellRect{};
  }
  applyMapChanges(*changes, *made.cells);  // throws before writing a cell: made.rect still says what it holds
  made.rect = rect;
  noteReturned(made.cells, rect);
  return made.cells;
}

}  // namespace beft::planners
