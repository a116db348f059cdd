#include "tools/bench_camera/packing_table.hpp"

#include <time.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <beft/robot_command_t.hpp>
#include <opencv2/imgcodecs.hpp>

#include "lib/camera/frame_compressor.hpp"
#include "lib/camera/frame_decoding.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "sim/world/world_simulation.hpp"

namespace beft::bench {

namespace {

using beft::camera_frame_t;

double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

std::vector<camera::CameraMessages> drivingFrames(const std::string& scenario_path, int ticks) {
  const auto scenario = scenario::loadScenario(scenario_path);
  world::WorldSimulation world(scenario, world::WorldOptions{});
  std::vector<camera::CameraMessages> frames(static_cast<std::size_t>(ticks));
  for (int k = 0; k < ticks; ++k) {
    if (k > 0) {
      robot_command_t command{};
      command.mode = robot_command_t::MODE_VELOCITY;
      const double heading = world.robotState().yaw * M_PI / 180.0;
      command.vx = 0.4 * std::cos(heading);
      command.vy = 0.4 * std::sin(heading);
      command.yaw_rate = 20;
      command.source = "bench";
      world.submitCommand(command);
      world.step();
    }
    world.cameraMessages(frames[static_cast<std::size_t>(k)]);
  }
  return frames;
}

const char* compressionName(int8_t compression) {
  switch (compression) {
    case camera_frame_t::COMPRESSION_NONE: return "none";
    case camera_frame_t::COMPRESSION_ZSTD: return "zstd";
    case camera_frame_t::COMPRESSION_ZSTD_SUB: return "sub + zstd";
    case camera_frame_t::COMPRESSION_ZSTD_UP: return "up + zstd";
  }
  return "?";
}

struct Row {
  double bytes = 0, pack_us = 0, unpack_us = 0;
};

Row measurePacking(const std::vector<const camera_frame_t*>& frames, const camera::Packing& packing) {
  camera::FrameCompressor compressor;
  camera_frame_t packed{}, pixels{};
  Row row;
  for (const camera_frame_t* frame : frames) {
    const double start = threadSeconds();
    compressor.compress(*frame, packing, packed);
    const double packed_at = threadSeconds();
    if (!camera::decodeCameraFrame(packed, pixels) || pixels.data != frame->data)
      std::fprintf(stderr, "bench: a frame did not come back exactly\n");
    row.bytes += static_cast<double>(packed.data.size());
    row.pack_us += 1e6 * (packed_at - start);
    row.unpack_us += 1e6 * (threadSeconds() - packed_at);
  }
  const double n = static_cast<double>(frames.size());
  return {row.bytes / n, row.pack_us / n, row.unpack_us / n};
}

// OpenCV's PNG (zlib, its default level and filter choice), for comparison.
Row measurePng(const std::vector<const camera_frame_t*>& frames) {
  Row row;
  std::vector<uint8_t> png;
  std::vector<uint16_t> values;
  for (const camera_frame_t* frame : frames) {
    const double start = threadSeconds();
    if (frame->encoding == camera_frame_t::ENCODING_RGB8) {
      const cv::Mat image(frame->height, frame->width, CV_8UC3, const_cast<uint8_t*>(frame->data.data()));
      cv::imencode(".png", image, png);
    } else {
      values.resize(frame->data.size() / 2);
      for (std::size_t i = 0; i < values.size(); ++i)
        values[i] = static_cast<uint16_t>(frame->data[2 * i] | (frame->data[2 * i + 1] << 8));
      const cv::Mat image(frame->height, frame->width, CV_16UC1, values.data());
      cv::imencode(".png", image, png);
    }
    const double packed_at = threadSeconds();
    const cv::Mat back = cv::imdecode(png, cv::IMREAD_UNCHANGED);
    row.bytes += static_cast<double>(png.size());
    row.pack_us += 1e6 * (packed_at - start);
    row.unpack_us += 1e6 * (threadSeconds() - packed_at);
  }
  const double n = static_cast<double>(frames.size());
  return {row.bytes / n, row.pack_us / n, row.unpack_us / n};
}

}  // namespace

void printPackingTable(const std::string& scenario_path, int ticks) {
  const std::vector<camera::CameraMessages> ticks_rendered = drivingFrames(scenario_path, ticks);
  std::printf("\nFrame compression over %d ticks of %s (the robot driving and turning), per frame: payload bytes, "
              "CPU time to pack and to unpack; * the packing the world uses:\n",
              ticks, scenario_path.c_str());
  std::printf("%-12s %-12s %6s %10s %10s %10s\n", "encoding", "packing", "level", "bytes", "pack us", "unpack us");
  const struct {
    const char* name;
    int8_t encoding;
  } encodings[] = {{"RGB8", camera_frame_t::ENCODING_RGB8},
                   {"DEPTH_MM16", camera_frame_t::ENCODING_DEPTH_MM16},
                   {"INSTANCE16", camera_frame_t::ENCODING_INSTANCE16}};
  double chosen_bytes = 0, raw_bytes = 0;
  for (const auto& encoding : encodings) {
    std::vector<const camera_frame_t*> frames;
    for (const auto& tick : ticks_rendered) {
      const camera_frame_t* frame = encoding.encoding == camera_frame_t::ENCODING_RGB8 ? &tick.color
                                    : encoding.encoding == camera_frame_t::ENCODING_DEPTH_MM16 ? &tick.depth
                                                                                             : &tick.instance;
      frames.push_back(frame);
    }
    const camera::Packing chosen = camera::packingFor(encoding.encoding);
    for (const int8_t compression : {camera_frame_t::COMPRESSION_NONE, camera_frame_t::COMPRESSION_ZSTD,
                                     camera_frame_t::COMPRESSION_ZSTD_SUB, camera_frame_t::COMPRESSION_ZSTD_UP}) {
      for (const int level : {1, 3, 5}) {
        if (compression == camera_frame_t::COMPRESSION_NONE && level > 1) continue;
        const camera::Packing packing{compression, compression == camera_frame_t::COMPRESSION_NONE ? 0 : level};
        const Row row = measurePacking(frames, packing);
        const bool is_chosen = packing.compression == chosen.compression && packing.level == chosen.level;
        if (is_chosen) chosen_bytes += row.bytes;
        if (compression == camera_frame_t::COMPRESSION_NONE) raw_bytes += row.bytes;
        std::printf("%-12s %-12s %6d %10.0f %10.1f %10.1f%s\n", encoding.name, compressionName(compression),
                    packing.level, row.bytes, row.pack_us, row.unpack_us, is_chosen ? " *" : "");
      }
    }
    const Row png = measurePng(frames);
    std::printf("%-12s %-12s %6s %10.0f %10.1f %10.1f\n", encoding.name, "PNG (OpenCV)", "-", png.bytes, png.pack_us,
                png.unpack_us);
  }
  std::printf("a tick's three frames: %.0f bytes packed as chosen, %.0f raw (%.1fx smaller)\n", chosen_bytes,
              raw_bytes, raw_bytes / chosen_bytes);
}

}  // namespace beft::bench
