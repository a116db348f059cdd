// Ground footprints (rotated boxes, cylinders) and the WAV check.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "lib/scenario/footprint.hpp"
#include "tests/lib/scenario/scenario_test_dir.hpp"
#include "lib/scenario/wav_info.hpp"

namespace beft::scenario {
namespace {

Object box(double x, double y, double yaw, double sx, double sy) {
  Object object;
  object.x = x;
  object.y = y;
  object.yaw = yaw;
  object.visual = Visual{};
  object.visual->shape = Visual::Shape::Box;
  object.visual->size_x = sx;
  object.visual->size_y = sy;
  object.visual->size_z = 1;
  return object;
}

TEST(Footprint, AxisAlignedBox) {
  const Object wall = box(10, 5, 0, 4, 0.2);  // x in [8, 12], y in [4.9, 5.1]
  EXPECT_DOUBLE_EQ(distanceToFootprint(wall, 10, 5), 0);
  EXPECT_DOUBLE_EQ(distanceToFootprint(wall, 11.9, 5.05), 0);
  EXPECT_NEAR(distanceToFootprint(wall, 10, 6.1), 1.0, 1e-12);
  EXPECT_NEAR(distanceToFootprint(wall, 13, 5), 1.0, 1e-12);
  EXPECT_NEAR(distanceToFootprint(wall, 15, 9.1), 5.0, 1e-12);  // corner (12, 5.1): 3-4-5
}

TEST(Footprint, BoxRotatedByYaw) {
  const Object wall = box(10, 5, 90, 4, 0.2);  // now x in [9.9, 10.1], y in [3, 7]
  EXPECT_DOUBLE_EQ(distanceToFootprint(wall, 10, 6.9), 0);
  EXPECT_NEAR(distanceToFootprint(wall, 11.9, 5), 1.8, 1e-9);
  EXPECT_NEAR(distanceToFootprint(wall, 10, 8), 1.0, 1e-9);
  const Object diagonal = box(0, 0, 45, 2, 2);  // a diamond reaching to x = sqrt(2)
  EXPECT_NEAR(distanceToFootprint(diagonal, 2, 0), 2 - std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(distanceToFootprint(diagonal, 1, 1), std::sqrt(2.0) - 1, 1e-9);
}

TEST(Footprint, CylinderAndInvisibleObject) {
  Object person;
  person.x = 3;
  person.y = 4;
  person.visual = Visual{};
  person.visual->shape = Visual::Shape::Cylinder;
  person.visual->radius = 0.5;
  EXPECT_DOUBLE_EQ(distanceToFootprint(person, 3.2, 4), 0);
  EXPECT_NEAR(distanceToFootprint(person, 0, 0), 4.5, 1e-12);
  Object radio;
  EXPECT_TRUE(std::isinf(distanceToFootprint(radio, 0, 0)));
}

using WavInfoTest = testing::ScenarioTestDir;

TEST_F(WavInfoTest, ReportsRateChannelsFramesAndDuration) {
  const std::string path = (dir_ / "tone.wav").string();
  testing::writeTone(path, 1.25);
  const WavInfo info = readWavInfo(path);
  EXPECT_EQ(info.sample_rate, 16000);
  EXPECT_EQ(info.channels, 1);
  EXPECT_EQ(info.frames, 20000);
  EXPECT_DOUBLE_EQ(info.duration, 1.25);
}

TEST_F(WavInfoTest, RefusesMissingTextAndEmptyFiles) {
  EXPECT_THROW(readWavInfo((dir_ / "absent.wav").string()), WavError);
  try {
    readWavInfo((dir_ / "sounds" / "not_a_wav.wav").string());
    ADD_FAILURE() << "read a text file as a WAV";
  } catch (const WavError& error) {
    EXPECT_NE(std::string(error.what()).find("not_a_wav.wav"), std::string::npos) << error.what();
  }
  const std::string empty = (dir_ / "empty.wav").string();
  testing::writeTone(empty, 0);
  try {
    readWavInfo(empty);
    ADD_FAILURE() << "accepted a WAV without samples";
  } catch (const WavError& error) {
    EXPECT_NE(std::string(error.what()).find("no samples"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace beft::scenario
