#include "lib/wire/obstacle_map_codec.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace beft::planners {
namespace {

constexpr uint8_t kUnknown = beft::obstacle_map_t::CELL_UNKNOWN;
constexpr uint8_t kFree = beft::obstacle_map_t::CELL_FREE;
constexpr uint8_t kOccupied = beft::obstacle_map_t::CELL_OCCUPIED;

ObstacleCells sampleMap() {
  ObstacleCells map;
  map.width = 300;  // rows longer than one RLE run
  map.height = 4;
  map.resolution = 0.05;
  map.origin_x = -1.5;
  map.origin_y = 2.0;
  map.cells.assign(300 * 4, kUnknown);
  for (int x = 10; x < 290; ++x) map.cells[300 + x] = kFree;
  for (int x = 0; x < 300; x += 7) map.cells[600 + x] = kOccupied;
  return map;
}

TEST(ObstacleMapCodec, RleSplitsRunsLongerThan255) {
  const std::vector<uint8_t> cells(600, kFree);
  const auto data = encodeRle(cells);
  ASSERT_EQ(data.size(), 6u);  // 255 + 255 + 90
  EXPECT_EQ(data[0], 255);
  EXPECT_EQ(data[2], 255);
  EXPECT_EQ(data[4], 90);
  EXPECT_EQ(data[5], kFree);
  EXPECT_EQ(decodeRle(data, 600), cells);
}

TEST(ObstacleMapCodec, RoundTripEveryEncoding) {
  const ObstacleCells map = sampleMap();
  for (int8_t encoding : {beft::obstacle_map_t::ENCODING_RAW, beft::obstacle_map_t::ENCODING_RLE,
                          beft::obstacle_map_t::ENCODING_RLE_ZSTD}) {
    const auto msg = makeObstacleMap(map, encoding, 123, 4);
    EXPECT_EQ(msg.data_size, static_cast<int32_t>(msg.data.size()));
    EXPECT_EQ(msg.utime, 123);
    EXPECT_EQ(msg.tick, 4);
    const ObstacleCells back = decodeObstacleMap(msg);
    EXPECT_EQ(back.width, map.width);
    EXPECT_EQ(back.height, map.height);
    EXPECT_DOUBLE_EQ(back.resolution, map.resolution);
    EXPECT_DOUBLE_EQ(back.origin_x, map.origin_x);
    EXPECT_DOUBLE_EQ(back.origin_y, map.origin_y);
    EXPECT_EQ(back.cells, map.cells);
    EXPECT_EQ(back.at(7, 2), kOccupied);
    EXPECT_EQ(back.at(8, 2), kUnknown);
  }
}

TEST(ObstacleMapCodec, RleEncodesEveryRunLengthAsTheBytewiseDefinition) {
  // Runs of every length around the 8-cell words the encoder compares and the 255-cell limit.
  std::mt19937 rng(9);
  std::vector<uint8_t> cells;
  std::vector<std::pair<size_t, uint8_t>> runs;
  for (int i = 0; i < 400; ++i) {
    const size_t length = 1 + rng() % (i % 4 == 0 ? 600 : 20);
    const uint8_t value = static_cast<uint8_t>((runs.empty() ? 0 : runs.back().second + 1 + rng() % 2) % 3);
    runs.push_back({length, value});
    cells.insert(cells.end(), length, value);
  }
  std::vector<uint8_t> expected;  // (count, value) pairs, a new pair after 255 cells or a change
  for (size_t i = 0; i < cells.size();) {
    size_t run = 1;
    while (i + run < cells.size() && cells[i + run] == cells[i] && run < 255) ++run;
    expected.push_back(static_cast<uint8_t>(run));
    expected.push_back(cells[i]);
    i += run;
  }
  EXPECT_EQ(encodeRle(cells), expected);
  EXPECT_EQ(decodeRle(encodeRle(cells), cells.size()), cells);
  EXPECT_TRUE(encodeRle({}).empty());
}

TEST(ObstacleMapCodec, RleIsSmallForTypicalMaps) {
  // A 30 x 20 m world at 0.1 m: 60000 cells must fit one UDP datagram.
  ObstacleCells map;
  map.width = 300;
  map.height = 200;
  map.cells.assign(60000, kFree);
  for (int y = 50; y < 150; ++y) map.cells[y * 300 + 100] = kOccupied;
  const auto msg = makeObstacleMap(map, beft::obstacle_map_t::ENCODING_RLE);
  EXPECT_LT(msg.getEncodedSize(), 64 * 1024);
}

TEST(ObstacleMapCodec, ZstdPacksTheRleOfABigMapSmaller) {
  // A 160 x 120 m world at 0.1 m: rooms of walls in free space, unknown beyond.
  ObstacleCells map;
  map.width = 1600;
  map.height = 1200;
  map.cells.assign(static_cast<size_t>(map.width) * map.height, kUnknown);
  for (int y = 100; y < 700; ++y)
    for (int x = 100; x < 900; ++x) map.cells[static_cast<size_t>(y) * map.width + x] = (x % 50 == 0 || y % 40 == 0) ? kOccupied : kFree;
  const auto rle = makeObstacleMap(map, beft::obstacle_map_t::ENCODING_RLE);
  const auto packed = makeObstacleMap(map, beft::obstacle_map_t::ENCODING_RLE_ZSTD);
  EXPECT_LT(packed.data.size() * 4, rle.data.size());
  EXPECT_EQ(decodeObstacleMap(packed).cells, map.cells);
}

TEST(ObstacleMapCodec, RejectsDamagedOrOversizedZstd) {
  const ObstacleCells map = sampleMap();
  auto msg = makeObstacleMap(map, beft::obstacle_map_t::ENCODING_RLE_ZSTD);
  auto cut = msg;
  cut.data.resize(cut.data.size() / 2);
  cut.data_size = static_cast<int32_t>(cut.data.size());
  EXPECT_THROW(decodeObstacleMap(cut), ObstacleMapError);
  auto garbage = msg;
  for (auto& byte : garbage.data) byte = 0x5a;
  EXPECT_THROW(decodeObstacleMap(garbage), ObstacleMapError);
  // A frame claiming more than the map's RLE could take is refused before it is unpacked.
  ObstacleCells bigger = map;
  bigger.width = 3000;
  bigger.cells.assign(static_cast<size_t>(bigger.width) * bigger.height, kUnknown);
  for (size_t i = 0; i < bigger.cells.size(); i += 2) bigger.cells[i] = kFree;  // RLE of 2 bytes per cell
  auto claims = makeObstacleMap(bigger, beft::obstacle_map_t::ENCODING_RLE_ZSTD);
  claims.width = map.width;
  try {
    decodeObstacleMap(claims);
    FAIL() << "an oversized frame was unpacked";
  } catch (const ObstacleMapError& e) {
    EXPECT_NE(std::string(e.what()).find("more than"), std::string::npos) << e.what();
  }
}

TEST(ObstacleMapCodec, RejectsMalformedRle) {
  EXPECT_THROW(decodeRle({3, kFree, 2}, 5), ObstacleMapError);       // odd length
  EXPECT_THROW(decodeRle({0, kFree, 5, kFree}, 5), ObstacleMapError);  // zero count
  EXPECT_THROW(decodeRle({3, kFree}, 5), ObstacleMapError);           // too few cells
  EXPECT_THROW(decodeRle({3, kFree, 3, kFree}, 5), ObstacleMapError);  // too many
}

TEST(ObstacleMapCodec, RejectsInconsistentMessages) {
  const auto good = makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RLE);
  auto bad = good;
  bad.data_size += 1;
  EXPECT_THROW(decodeObstacleMap(bad), ObstacleMapError);
  bad = good;
  bad.width = 0;
  EXPECT_THROW(decodeObstacleMap(bad), ObstacleMapError);
  bad = good;
  bad.resolution = -0.1;
  EXPECT_THROW(decodeObstacleMap(bad), ObstacleMapError);
  bad = good;
  bad.encoding = 7;
  EXPECT_THROW(decodeObstacleMap(bad), ObstacleMapError);
  bad = makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RAW);
  bad.data[5] = 9;  // not a CELL_* value
  EXPECT_THROW(decodeObstacleMap(bad), ObstacleMapError);
  bad = makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RAW);
  bad.height = 5;  // more cells than data
  EXPECT_THROW(decodeObstacleMap(bad), ObstacleMapError);
  // Absurd sizes are refused before anything is allocated for them.
  bad = good;
  bad.width = bad.height = 2000000000;
  EXPECT_THROW(decodeObstacleMap(bad), ObstacleMapError);
}

TEST(ObstacleMapCodec, NamesTheFirstBadCellWhereverItIs) {
  for (const std::size_t bad_index : {std::size_t{0}, std::size_t{599}, std::size_t{1199}}) {
    auto bad = makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RAW);
    bad.data[bad_index] = 3;
    try {
      decodeObstacleMap(bad);
      ADD_FAILURE() << "cell " << bad_index << " = 3 was accepted";
    } catch (const ObstacleMapError& e) {
      EXPECT_NE(std::string(e.what()).find("cell " + std::to_string(bad_index) + " has value 3"), std::string::npos)
          << e.what();
    }
  }
  auto bad_rle = makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RLE);
  bad_rle.data[1] = 200;  // the value of the first run
  EXPECT_THROW(decodeObstacleMap(bad_rle), ObstacleMapError);
}

TEST(ObstacleMapCodec, SameEncodedMapIgnoresTimeOnly) {
  const auto first = makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RLE, 100, 1);
  auto later = makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RLE, 200, 2);
  EXPECT_TRUE(sameEncodedMap(first, later));
  ObstacleCells changed = sampleMap();
  changed.cells[5] = kOccupied;
  EXPECT_FALSE(sameEncodedMap(first, makeObstacleMap(changed, beft::obstacle_map_t::ENCODING_RLE, 100, 1)));
  later.resolution = 0.1;
  EXPECT_FALSE(sameEncodedMap(first, later));
  EXPECT_FALSE(sameEncodedMap(first, makeObstacleMap(sampleMap(), beft::obstacle_map_t::ENCODING_RAW, 100, 1)));
}

TEST(ObstacleMapCodec, RefusesToEncodeWrongCellCount) {
  ObstacleCells map = sampleMap();
  map.cells.pop_back();
  EXPECT_THROW(makeObstacleMap(map, beft::obstacle_map_t::ENCODING_RLE), ObstacleMapError);
}

}  // namespace
}  // namespace beft::planners
