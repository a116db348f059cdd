// Which camera frames a recording keeps (--camera all | none | every:N), and
// the recorder keeping exactly those, every other message untouched.
#include "lib/launch/camera_sampling.hpp"
#include "services/record/recorded_ports.hpp"
#include "services/record/recorder.hpp"

#include <unistd.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/fire_t.hpp>
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

using beft::record::CameraSampling;

namespace {

std::vector<uint8_t> frameBytes(int64_t tick, int8_t encoding) {
  beft::camera_frame_t frame{};
  frame.utime = tick * 100000;
  frame.tick = tick;
  frame.encoding = encoding;
  frame.compression = beft::camera_frame_t::COMPRESSION_NONE;
  frame.width = 2;
  frame.height = 1;
  frame.data.assign(encoding == beft::camera_frame_t::ENCODING_RGB8 ? 6 : 4, static_cast<uint8_t>(tick));
  frame.data_size = static_cast<int32_t>(frame.data.size());
  std::vector<uint8_t> bytes(frame.getEncodedSize());
  frame.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

bool keeps(const CameraSampling& sampling, const std::string& channel, const std::vector<uint8_t>& bytes) {
  return sampling.keeps(channel, bytes.data(), bytes.size());
}

}  // namespace

TEST(CameraSampling, ParsesAllNoneAndEveryN) {
  EXPECT_EQ(CameraSampling::parse("all").text(), "all");
  EXPECT_EQ(CameraSampling::parse("none").text(), "none");
  EXPECT_EQ(CameraSampling::parse("every:5").text(), "every:5");
  EXPECT_EQ(CameraSampling::parse("every:1").text(), "all");
  EXPECT_TRUE(CameraSampling{}.keepsAll());
  for (const char* bad : {"", "every:", "every:0", "every:-2", "every:5x", "every 5", "some", "ALL"})
    EXPECT_THROW(CameraSampling::parse(bad), std::invalid_argument) << bad;
}

TEST(CameraSampling, KeepsTheFramesOfEveryNthTickOnEveryCameraChannelOfAnyRun) {
  const CameraSampling every5 = CameraSampling::parse("every:5");
  for (const std::string channel : {"CAMERA_COLOR", "CAMERA_DEPTH", "CAMERA_INSTANCE@3f2a"}) {
    std::vector<int64_t> kept;
    for (int64_t tick = 0; tick < 23; ++tick)
      if (keeps(every5, channel, frameBytes(tick, beft::camera_frame_t::ENCODING_DEPTH_MM16))) kept.push_back(tick);
    EXPECT_EQ(kept, (std::vector<int64_t>{0, 5, 10, 15, 20})) << channel;
  }
  // Off the camera channels everything is kept, frames or not.
  EXPECT_TRUE(keeps(every5, "CAMERA_COLOR_NOT", frameBytes(3, 0)));
  EXPECT_TRUE(keeps(every5, "VISION", frameBytes(3, 0)));
  // On them, what is no camera frame (its tick unreadable) is kept for its readers to judge.
  EXPECT_TRUE(keeps(every5, "CAMERA_DEPTH", std::vector<uint8_t>(40, 0x11)));
  const CameraSampling none = CameraSampling::parse("none");
  EXPECT_FALSE(keeps(none, "CAMERA_DEPTH", frameBytes(0, 1)));
  EXPECT_FALSE(keeps(none, "CAMERA_COLOR@1", std::vector<uint8_t>(40, 0x11)));
  EXPECT_TRUE(keeps(none, "GT_OBJECTS", frameBytes(0, 1)));
  EXPECT_TRUE(keeps(CameraSampling::parse("all"), "CAMERA_DEPTH", frameBytes(7, 1)));
}

TEST(Recorder, KeepsTheCameraFramesItIsToldToAndEveryOtherMessage) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("beft_test_camera_sampling_" + std::to_string(getpid()) + ".lcmlog"))
          .string();
  std::filesystem::remove(path);
  {
    lcm::LCM lcm("memq://");
    beft::record::RecordOptions options;
    options.path = path;
    options.camera = CameraSampling::parse("every:5");
    beft::record::Recorder recorder(lcm, "memq://", options, beft::record::RecordedPorts().taken());
    for (int64_t tick = 0; tick < 12; ++tick) {
      for (const auto& [channel, encoding] :
           {std::pair{"CAMERA_COLOR", 0}, {"CAMERA_DEPTH", 1}, {"CAMERA_INSTANCE", 2}}) {
        const auto bytes = frameBytes(tick, static_cast<int8_t>(encoding));
        lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
      }
      const std::string other = "tick " + std::to_string(tick);
      lcm.publish("GT_OBJECTS", other.data(), static_cast<unsigned>(other.size()));
    }
    recorder.drain(10, 2000);
    EXPECT_EQ(recorder.events(), 12 + 3 * 3);
    EXPECT_EQ(recorder.cameraFramesLeftOut(), 3 * 9);
  }
  lcm::LogFile log(path, "r");
  ASSERT_TRUE(log.good());
  std::map<std::string, std::vector<int64_t>> ticks;
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    const std::string channel = event->channel;
    if (channel == "GT_OBJECTS") {
      ticks[channel].push_back(static_cast<int64_t>(ticks[channel].size()));
      continue;
    }
    beft::camera_frame_t frame{};
    ASSERT_EQ(frame.decode(event->data, 0, event->datalen), event->datalen);
    ticks[channel].push_back(frame.tick);
  }
  EXPECT_EQ(ticks["CAMERA_COLOR"], (std::vector<int64_t>{0, 5, 10}));
  EXPECT_EQ(ticks["CAMERA_DEPTH"], (std::vector<int64_t>{0, 5, 10}));
  EXPECT_EQ(ticks["CAMERA_INSTANCE"], (std::vector<int64_t>{0, 5, 10}));
  EXPECT_EQ(ticks["GT_OBJECTS"].size(), 12u);
  std::filesystem::remove(path);
}
