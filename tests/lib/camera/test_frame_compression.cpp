// Camera frames packed for the wire (frame_compressor.hpp) and unpacked by
// the one decoder every reader uses (frame_decoding.hpp): every pixel comes
// back, and a payload that lies or is damaged is refused with its reason.
#include <gtest/gtest.h>
#include <zstd.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/robot_command_t.hpp>

#include "lib/camera/camera_messages.hpp"
#include "lib/common/channels.hpp"
#include "lib/camera/frame_compressor.hpp"
#include "lib/camera/frame_decoding.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/wire/log_reader.hpp"
#include "sim/world/world_simulation.hpp"

using beft::camera_frame_t;
using namespace beft::camera;

namespace {

std::vector<uint8_t> bytesOf(const camera_frame_t& frame) {
  std::vector<uint8_t> bytes(frame.getEncodedSize());
  frame.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// The frames of the short peek run committed as test data (recorded raw,
// before frames were compressed; the log reader gives them today's layout).
std::vector<camera_frame_t> recordedFrames() {
  beft::wire::LogReader log(std::string(BEFT_SOURCE_DIR) + "/tests/system/data/peek_6_ticks.lcmlog");
  std::vector<camera_frame_t> frames;
  beft::wire::LogEvent event;
  while (log.next(event)) {
    if (event.channel.rfind("CAMERA_", 0) != 0) continue;
    camera_frame_t frame{};
    EXPECT_TRUE(beft::wire::guardedDecode(event.data.data(), event.data.size(), frame).ok()) << event.channel;
    frames.push_back(std::move(frame));
  }
  return frames;
}

// Every frame of 80 ticks of yard.xml, the robot driving and turning (the
// head's view sweeps over walls, people, cars and sky).
const std::vector<CameraMessages>& yardTicks() {
  static const std::vector<CameraMessages> ticks = [] {
    const auto scenario = beft::scenario::loadScenario(std::string(BEFT_SOURCE_DIR) + "/scenarios/yard.xml");
    beft::world::WorldSimulation world(scenario, beft::world::WorldOptions{});
    std::vector<CameraMessages> frames;
    for (int k = 0; k < 80; ++k) {
      if (k > 0) {
        beft::robot_command_t command{};
        command.mode = beft::robot_command_t::MODE_VELOCITY;
        const double heading = world.robotState().yaw * M_PI / 180.0;
        command.vx = 0.5 * std::cos(heading);
        command.vy = 0.5 * std::sin(heading);
        command.yaw_rate = 25;
        command.source = "test";
        world.submitCommand(command);
        world.step();
      }
      frames.emplace_back();
      world.cameraMessages(frames.back());
    }
    return frames;
  }();
  return ticks;
}

// As a reader gets it: encoded, through the guard, then decoded.
camera_frame_t received(const camera_frame_t& sent) {
  const std::vector<uint8_t> bytes = bytesOf(sent);
  camera_frame_t frame{};
  EXPECT_TRUE(beft::wire::guardedDecode(bytes.data(), bytes.size(), frame).ok());
  return frame;
}

camera_frame_t packed(const camera_frame_t& raw) {
  FrameCompressor compressor;
  camera_frame_t out{};
  compressor.compress(raw, out);
  return out;
}

// A zstd frame of bytes with the given frame parameters.
std::vector<uint8_t> zstdFrame(const std::vector<uint8_t>& content, bool checksum, bool content_size) {
  ZSTD_CCtx* context = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(context, ZSTD_c_checksumFlag, checksum ? 1 : 0);
  ZSTD_CCtx_setParameter(context, ZSTD_c_contentSizeFlag, content_size ? 1 : 0);
  std::vector<uint8_t> out(ZSTD_compressBound(content.size()));
  std::size_t size = 0;
  if (content_size) {
    size = ZSTD_compress2(context, out.data(), out.size(), content.data(), content.size());
  } else {
    // Streamed: the size is not known when the header is written.
    ZSTD_inBuffer in{content.data(), content.size(), 0};
    ZSTD_outBuffer sink{out.data(), out.size(), 0};
    ZSTD_compressStream2(context, &sink, &in, ZSTD_e_end);
    size = sink.pos;
  }
  ZSTD_freeCCtx(context);
  out.resize(size);
  return out;
}

void setPayload(camera_frame_t& frame, std::vector<uint8_t> payload) {
  frame.data = std::move(payload);
  frame.data_size = static_cast<int32_t>(frame.data.size());
}

// The decoder refuses the frame with a reason containing `reason`, and
// leaves the frame it was to fill untouched.
void expectRefused(const camera_frame_t& frame, const std::string& reason) {
  camera_frame_t out{};
  out.width = -7;  // a mark: untouched after a refusal
  std::string why;
  EXPECT_FALSE(decodeCameraFrame(frame, out, &why)) << "expected a refusal: " << reason;
  EXPECT_NE(why.find(reason), std::string::npos) << "reason given: " << why;
  EXPECT_EQ(out.width, -7);
  camera_frame_t in_place = frame;
  EXPECT_FALSE(decodeCameraFrame(in_place, &why));
  // (Compared field by field: a frame whose num_ids lies cannot be encoded.)
  EXPECT_TRUE(in_place.data == frame.data && in_place.data_size == frame.data_size &&
              in_place.compression == frame.compression && in_place.width == frame.width &&
              in_place.height == frame.height)
      << "changed by a refused in-place decode";
}

}  // namespace

TEST(FrameCompression, EveryFrameOfTheRecordedRunComesBackExactly) {
  const std::vector<camera_frame_t> frames = recordedFrames();
  ASSERT_EQ(frames.size(), 18u);  // 6 ticks x colour, depth, instance
  std::map<int, int> per_encoding;
  for (const camera_frame_t& raw : frames) {
    std::string why;
    ASSERT_TRUE(validCameraFrame(raw, &why)) << why;
    const camera_frame_t sent = packed(raw);
    EXPECT_NE(sent.compression, camera_frame_t::COMPRESSION_NONE);
    EXPECT_LT(sent.data.size() * 4, raw.data.size()) << "encoding " << int(raw.encoding);
    camera_frame_t pixels{};
    ASSERT_TRUE(decodeCameraFrame(received(sent), pixels, &why)) << why;
    EXPECT_EQ(pixels.data, raw.data) << "tick " << raw.tick << " encoding " << int(raw.encoding);
    EXPECT_EQ(bytesOf(pixels), bytesOf(raw)) << "header of tick " << raw.tick;
    ++per_encoding[raw.encoding];
  }
  EXPECT_EQ(per_encoding, (std::map<int, int>{{0, 6}, {1, 6}, {2, 6}}));
}

TEST(FrameCompression, EveryFrameOfADrivingYardRunComesBackExactly) {
  FrameCompressor compressor;
  std::size_t frames = 0;
  for (const CameraMessages& raw : yardTicks()) {
    CameraMessages sent;
    compressor.compress(raw, sent);
    for (const auto& [original, packed_frame] :
         {std::pair{&raw.color, &sent.color}, {&raw.depth, &sent.depth}, {&raw.instance, &sent.instance}}) {
      camera_frame_t pixels = received(*packed_frame);
      std::string why;
      ASSERT_TRUE(decodeCameraFrame(pixels, &why)) << why;
      ASSERT_EQ(pixels.data, original->data) << "tick " << original->tick << " encoding " << int(original->encoding);
      EXPECT_EQ(bytesOf(pixels), bytesOf(*original));
      ++frames;
    }
  }
  EXPECT_EQ(frames, 240u);
}

TEST(FrameCompression, EveryPackingRoundTripsEveryEncoding) {
  const CameraMessages& raw = yardTicks().at(40);
  FrameCompressor compressor;
  for (const camera_frame_t* frame : {&raw.color, &raw.depth, &raw.instance}) {
    for (const Packing packing :
         {Packing{camera_frame_t::COMPRESSION_NONE, 0}, Packing{camera_frame_t::COMPRESSION_ZSTD, 1},
          Packing{camera_frame_t::COMPRESSION_ZSTD_SUB, 1}, Packing{camera_frame_t::COMPRESSION_ZSTD_UP, 3}}) {
      camera_frame_t sent{};
      compressor.compress(*frame, packing, sent);
      EXPECT_EQ(sent.compression, packing.compression);
      camera_frame_t pixels{};
      std::string why;
      ASSERT_TRUE(decodeCameraFrame(received(sent), pixels, &why)) << why;
      EXPECT_EQ(bytesOf(pixels), bytesOf(*frame))
          << "encoding " << int(frame->encoding) << ", compression " << int(packing.compression);
    }
  }
}

TEST(FrameCompression, AYardTickTakesAFewKilobytes) {
  // Raw, a tick's three frames are 134 kB: most of a run's log.
  FrameCompressor compressor;
  std::map<int, std::size_t> bytes;
  for (const CameraMessages& raw : yardTicks()) {
    CameraMessages sent;
    compressor.compress(raw, sent);
    bytes[0] += sent.color.data.size();
    bytes[1] += sent.depth.data.size();
    bytes[2] += sent.instance.data.size();
  }
  const std::size_t ticks = yardTicks().size();
  EXPECT_LT(bytes[0] / ticks, 8000u) << "colour";
  EXPECT_LT(bytes[1] / ticks, 1500u) << "depth";
  EXPECT_LT(bytes[2] / ticks, 600u) << "instance";
}

TEST(FrameCompression, ACompressorRefusesAFrameThatDoesNotHoldItsPixels) {
  camera_frame_t frame = yardTicks().at(0).depth;
  frame.data.pop_back();
  FrameCompressor compressor;
  camera_frame_t out{};
  EXPECT_THROW(compressor.compress(frame, out), std::invalid_argument);
}

TEST(FrameDecoding, RefusesDamagedOrLyingPayloadsWithTheReason) {
  const camera_frame_t good = packed(yardTicks().at(40).depth);  // 160 x 120, 38400 bytes of pixels
  ASSERT_EQ(good.compression, camera_frame_t::COMPRESSION_ZSTD);
  ASSERT_GT(good.data.size(), 40u);
  {
    camera_frame_t copy = good;
    std::string why;
    ASSERT_TRUE(decodeCameraFrame(copy, &why)) << why;  // the base case decodes
  }
  camera_frame_t frame = good;
  frame.data.resize(frame.data.size() - 9);
  frame.data_size = static_cast<int32_t>(frame.data.size());
  expectRefused(frame, "not a zstd frame");

  frame = good;
  frame.data[frame.data.size() / 2] ^= 0x10;  // damage inside: the checksum (or the entropy decoder) catches it
  expectRefused(frame, "zstd payload refused");

  frame = good;
  frame.data.push_back(0);
  frame.data_size += 1;
  expectRefused(frame, "followed by 1 other bytes");

  frame = good;
  frame.width = 80;  // the header lies about the size: the payload declares another
  expectRefused(frame, "declares 38400 bytes, but 80x120 pixels are 19200");

  frame = good;
  frame.compression = 9;
  expectRefused(frame, "unknown compression 9");

  frame = good;
  frame.data_size -= 1;
  expectRefused(frame, "data_size");

  frame = good;
  setPayload(frame, {});
  expectRefused(frame, "not a zstd frame");

  frame = good;
  setPayload(frame, std::vector<uint8_t>(500, 0x5a));
  expectRefused(frame, "not a zstd frame");

  const std::vector<uint8_t> pixels = yardTicks().at(40).depth.data;
  frame = good;
  setPayload(frame, zstdFrame(pixels, false, true));
  expectRefused(frame, "without a checksum");

  frame = good;
  setPayload(frame, zstdFrame(pixels, true, false));
  expectRefused(frame, "without its content size");

  frame = good;
  frame.compression = camera_frame_t::COMPRESSION_NONE;  // raw, but not width x height x 2 bytes
  expectRefused(frame, "data_size");
}

TEST(FrameDecoding, ADecompressionBombIsRefusedBeforeAnythingIsSized) {
  // 8 MiB of zeros packs into a few hundred bytes; the header says 160 x 120.
  camera_frame_t frame = packed(yardTicks().at(0).depth);
  setPayload(frame, zstdFrame(std::vector<uint8_t>(std::size_t{8} << 20, 0), true, true));
  ASSERT_LT(frame.data.size(), 2000u);
  expectRefused(frame, "declares 8388608 bytes");
  // A header may not claim more than a frame can hold either.
  frame.width = 1 << 20;
  frame.height = 1 << 20;
  expectRefused(frame, "pixels accepted");
  frame.width = -160;
  expectRefused(frame, "image size");
}

TEST(FrameDecoding, AnInstanceFrameMustNameItsIds) {
  camera_frame_t frame = packed(yardTicks().at(0).instance);
  ASSERT_GT(frame.num_ids, 0);
  frame.num_ids += 1;
  expectRefused(frame, "num_ids");
}

TEST(FrameDecoding, TheGuardRefusesAnUndeclaredCompressionBeforeDecoding) {
  camera_frame_t frame = packed(yardTicks().at(0).color);
  frame.compression = 4;
  const std::vector<uint8_t> bytes = bytesOf(frame);
  camera_frame_t decoded{};
  const beft::wire::Verdict verdict = beft::wire::guardedDecode(bytes.data(), bytes.size(), decoded);
  EXPECT_EQ(verdict.fault, beft::wire::Fault::kBadEnum);
  EXPECT_STREQ(verdict.field, "camera_frame_t.compression");
}
