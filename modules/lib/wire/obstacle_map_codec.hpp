// Encoding and decoding of the obstacle map message (beft::obstacle_map_t,
// channel OBSTACLE_MAP): cells row by row, row index along +y, one value
// CELL_UNKNOWN / CELL_FREE / CELL_OCCUPIED per cell, stored RAW (one byte per
// cell), RLE (pairs: count 1..255, value) or RLE_ZSTD (those pairs as one zstd
// frame, zstd from Debian's libzstd: a 160 x 120 m map's 70 kB of RLE become
// about 17 kB). Small and free of planning code so
// any process that reads or writes maps can link it (target beft_obstacle_map).
#pragma once

#include <beft/obstacle_map_t.hpp>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace beft::planners {

// A malformed map message: what is wrong with it.
class ObstacleMapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The cells of a map with its placement in the world.
struct ObstacleCells {
  int width = 0;            // cells along x
  int height = 0;           // cells along y
  double resolution = 0.1;  // cell edge [m]
  double origin_x = 0;      // world x of the corner of cell (0,0) [m]
  double origin_y = 0;      // world y of the corner of cell (0,0) [m]
  std::vector<uint8_t> cells;  // width * height values CELL_*, row by row

  uint8_t at(int x, int y) const { return cells[static_cast<size_t>(y) * width + x]; }
};

// Run-length encoding: (count 1..255, value) pairs; runs longer than 255 split.
std::vector<uint8_t> encodeRle(const std::vector<uint8_t>& cells);
// Inverse of encodeRle; throws ObstacleMapError on an odd length, a zero count
// or a total different from expected_cells.
std::vector<uint8_t> decodeRle(const std::vector<uint8_t>& data, size_t expected_cells);

// Builds a complete message (data_size set). encoding: ENCODING_RAW,
// ENCODING_RLE or ENCODING_RLE_ZSTD; throws ObstacleMapError when the cells do
// not fit the size.
beft::obstacle_map_t makeObstacleMap(const ObstacleCells& map, int8_t encoding,
                                     int64_t utime = 0, int64_t tick = 0);

// Decodes and validates a message: positive size and resolution, finite
// origin, data_size == data.size(), known encoding, the right number of
// cells, every value a CELL_* constant. Throws ObstacleMapError saying what is
// wrong.
ObstacleCells decodeObstacleMap(const beft::obstacle_map_t& message);

// True when two messages hold the same map (size, resolution, origin, encoding
// and bytes), whatever their time: a map republished unchanged need not be
// decoded again.
bool sameEncodedMap(const beft::obstacle_map_t& a, const beft::obstacle_map_t& b);

}  // namespace beft::planners
