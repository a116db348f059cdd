#include "lib/wire/obstacle_map_codec.hpp"

#include <zstd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <new>

namespace beft::planners {
namespace {

constexpr size_t kMaxRun = 255;

void checkCellValues(const std::vector<uint8_t>& cells) {
  // The highest value first (a loop the compiler vectorizes), the culprit only if there is one.
  uint8_t highest = 0;
  for (const uint8_t cell : cells) highest = std::max(highest, cell);
  if (highest <= static_cast<uint8_t>(beft::obstacle_map_t::CELL_OCCUPIED)) return;
  for (size_t i = 0; i < cells.size(); ++i) {
    if (cells[i] > static_cast<uint8_t>(beft::obstacle_map_t::CELL_OCCUPIED)) {
      throw ObstacleMapError("cell " + std::to_string(i) + " has value " +
                             std::to_string(cells[i]) + ", not a CELL_* constant (0, 1 or 2)");
    }
  }
}

}  // namespace

std::vector<uint8_t> encodeRle(const std::vector<uint8_t>& cells) {
  std::vector<uint8_t> out;
  out.reserve(4096);
  const uint8_t* data = cells.data();
  const size_t count = cells.size();
  size_t i = 0;
  while (i < count) {
    const uint8_t value = data[i];
    const size_t limit = std::min(count, i + kMaxRun);
    size_t end = i + 1;
    // Eight cells at a time while they all hold the value: maps are long runs.
    const uint64_t eight = 0x0101010101010101ull * value;
    for (uint64_t word; end + 8 <= limit; end += 8) {
      std::memcpy(&word, data + end, 8);
      if (word != eight) break;
    }
    while (end < limit && data[end] == value) ++end;
    out.push_back(static_cast<uint8_t>(end - i));
    out.push_back(value);
    i = end;
  }
  return out;
}

std::vector<uint8_t> decodeRle(const std::vector<uint8_t>& data, size_t expected_cells) {
  if (data.size() % 2 != 0) {
    throw ObstacleMapError("RLE data has an odd length (" + std::to_string(data.size()) +
                           " bytes); it must be (count, value) pairs");
  }
  std::vector<uint8_t> cells(expected_cells);
  uint8_t* out = cells.data();
  size_t filled = 0;
  for (size_t i = 0; i < data.size(); i += 2) {
    const size_t count = data[i];
    if (count == 0) throw ObstacleMapError("RLE pair at byte " + std::to_string(i) + " has count 0");
    if (filled + count > expected_cells) {
      throw ObstacleMapError("RLE data holds more than the " + std::to_string(expected_cells) +
                             " cells of the map");
    }
    std::memset(out + filled, data[i + 1], count);
    filled += count;
  }
  if (filled != expected_cells) {
    throw ObstacleMapError("RLE data holds " + std::to_string(filled) + " cells, the map has " +
                           std::to_string(expected_cells));
  }
  return cells;
}

namespace {

constexpr int kZstdLevel = 1;  // the fastest: a map is packed at every tick

// One context per thread, kept: making one costs about half of packing or
// unpacking a tick's change of the map. The bytes are those of
// ZSTD_compress at the same level.
ZSTD_CCtx* compressionContext() {
  thread_local const std::unique_ptr<ZSTD_CCtx, size_t (*)(ZSTD_CCtx*)> context(ZSTD_createCCtx(), ZSTD_freeCCtx);
  if (!context) throw std::bad_alloc();
  return context.get();
}

ZSTD_DCtx* decompressionContext() {
  thread_local const std::unique_ptr<ZSTD_DCtx, size_t (*)(ZSTD_DCtx*)> context(ZSTD_createDCtx(), ZSTD_freeDCtx);
  if (!context) throw std::bad_alloc();
  return context.get();
}

std::vector<uint8_t> compressZstd(const std::vector<uint8_t>& bytes) {
  std::vector<uint8_t> packed(ZSTD_compressBound(bytes.size()));
  const size_t size =
      ZSTD_compressCCtx(compressionContext(), packed.data(), packed.size(), bytes.data(), bytes.size(), kZstdLevel);
  if (ZSTD_isError(size)) throw ObstacleMapError(std::string("zstd: ") + ZSTD_getErrorName(size));
  packed.resize(size);
  return packed;
}

std::vector<uint8_t> decompressZstd(const std::vector<uint8_t>& packed, size_t max_bytes) {
  const unsigned long long size = ZSTD_getFrameContentSize(packed.data(), packed.size());
  if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN)
    throw ObstacleMapError("RLE_ZSTD data is not one zstd frame with its size");
  if (size > max_bytes)
    throw ObstacleMapError("RLE_ZSTD data unpacks to " + std::to_string(size) + " bytes, more than the " +
                           std::to_string(max_bytes) + " the map's RLE can take");
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  const size_t got =
      ZSTD_decompressDCtx(decompressionContext(), bytes.data(), bytes.size(), packed.data(), packed.size());
  if (ZSTD_isError(got) || got != bytes.size())
    throw ObstacleMapError(std::string("RLE_ZSTD data does not unpack: ") +
                           (ZSTD_isError(got) ? ZSTD_getErrorName(got) : "short frame"));
  return bytes;
}

}  // namespace

beft::obstacle_map_t makeObstacleMap(const ObstacleCells& map, int8_t encoding, int64_t utime,
                                     int64_t tick) {
  if (map.width <= 0 || map.height <= 0) throw ObstacleMapError("map size must be positive");
  if (map.cells.size() != static_cast<size_t>(map.width) * map.height) {
    throw ObstacleMapError("map has " + std::to_string(map.cells.size()) + " cells, expected " +
                           std::to_string(map.width) + " x " + std::to_string(map.height));
  }
  checkCellValues(map.cells);
  beft::obstacle_map_t msg{};
  msg.utime = utime;
  msg.tick = tick;
  msg.width = map.width;
  msg.height = map.height;
  msg.resolution = map.resolution;
  msg.origin_x = map.origin_x;
  msg.origin_y = map.origin_y;
  msg.encoding = encoding;
  if (encoding == beft::obstacle_map_t::ENCODING_RAW) {
    msg.data = map.cells;
  } else if (encoding == beft::obstacle_map_t::ENCODING_RLE) {
    msg.data = encodeRle(map.cells);
  } else if (encoding == beft::obstacle_map_t::ENCODING_RLE_ZSTD) {
    msg.data = compressZstd(encodeRle(map.cells));
  } else {
    throw ObstacleMapError("unknown encoding " + std::to_string(encoding));
  }
  msg.data_size = static_cast<int32_t>(msg.data.size());
  return msg;
}

ObstacleCells decodeObstacleMap(const beft::obstacle_map_t& message) {
  if (message.width <= 0 || message.height <= 0) {
    throw ObstacleMapError("map size " + std::to_string(message.width) + " x " +
                           std::to_string(message.height) + " is not positive");
  }
  if (!(std::isfinite(message.resolution) && message.resolution > 0)) {
    throw ObstacleMapError("resolution " + std::to_string(message.resolution) +
                           " is not a positive number");
  }
  if (!std::isfinite(message.origin_x) || !std::isfinite(message.origin_y)) {
    throw ObstacleMapError("origin is not finite");
  }
  if (message.data_size < 0 || static_cast<size_t>(message.data_size) != message.data.size()) {
    throw ObstacleMapError("data_size " + std::to_string(message.data_size) + " differs from the " +
                           std::to_string(message.data.size()) + " bytes of data");
  }
  ObstacleCells map;
  map.width = message.width;
  map.height = message.height;
  map.resolution = message.resolution;
  map.origin_x = message.origin_x;
  map.origin_y = message.origin_y;
  const size_t cell_count = static_cast<size_t>(message.width) * message.height;
  // A received map sizes an allocation: a map larger than any world the
  // project plans in (2^28 cells: 800 x 800 m at 5 cm) is refused, not allocated.
  constexpr size_t kMaxCells = size_t{1} << 28;
  if (cell_count > kMaxCells)
    throw ObstacleMapError("map of " + std::to_string(message.width) + " x " + std::to_string(message.height) +
                           " cells exceeds the limit of " + std::to_string(kMaxCells) + " cells");
  if (message.encoding == beft::obstacle_map_t::ENCODING_RAW) {
    if (message.data.size() != cell_count) {
      throw ObstacleMapError("RAW data has " + std::to_string(message.data.size()) +
                             " bytes, the map has " + std::to_string(cell_count) + " cells");
    }
    map.cells = message.data;
  } else if (message.encoding == beft::obstacle_map_t::ENCODING_RLE) {
    map.cells = decodeRle(message.data, cell_count);
  } else if (message.encoding == beft::obstacle_map_t::ENCODING_RLE_ZSTD) {
    // RLE of n cells takes at most 2n bytes: a frame claiming more is refused before any allocation.
    map.cells = decodeRle(decompressZstd(message.data, 2 * cell_count), cell_count);
  } else {
    throw ObstacleMapError("unknown encoding " + std::to_string(message.encoding));
  }
  checkCellValues(map.cells);
  return map;
}

bool sameEncodedMap(const beft::obstacle_map_t& a, const beft::obstacle_map_t& b) {
  return a.width == b.width && a.height == b.height && a.resolution == b.resolution && a.origin_x == b.origin_x &&
         a.origin_y == b.origin_y && a.encoding == b.encoding && a.data == b.data;
}

}  // namespace beft::planners
