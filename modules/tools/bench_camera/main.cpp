// beft-bench-camera (./beft bench camera): frames per second of the RGBD ray
// caster for 160x120 and 640x480 images over random scenes of 10 to 1000
// objects, for each render method, with brute force as the baseline.
#include <time.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <optional>
#include <vector>

#include <CLI/CLI.hpp>

#include "lib/camera/camera_messages.hpp"
#include "lib/common/command_line.hpp"
#include "lib/camera/frame_compressor.hpp"
#include "tools/bench_camera/packing_table.hpp"
#include "lib/scene/ray_caster.hpp"
#include "lib/scene/scene_geometry.hpp"

using namespace beft::camera;

namespace {

struct BenchScene {
  SceneGeometry geometry;
  std::vector<Camera> cameras;  // poses cycled through, all clear of objects
};

// Walls, crates and persons scattered over a width x height yard.
BenchScene randomScene(int objects, double width, double height, int image_width, int image_height,
                       uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> x(0, width), y(0, height), angle(0, 360), unit(0, 1);
  BenchScene scene;
  scene.geometry.setObjectCount(objects);
  for (int i = 0; i < objects; ++i) {
    const double kind = unit(random);
    if (kind < 0.3) {
      scene.geometry.addBox(i, x(random), y(random), 0, angle(random), 1 + 4 * unit(random), 0.2, 2 + unit(random),
                            0x808080);
    } else if (kind < 0.6) {
      scene.geometry.addBox(i, x(random), y(random), 0, angle(random), 0.5 + 1.5 * unit(random),
                            0.5 + 1.5 * unit(random), 0.5 + 1.5 * unit(random), 0x8a6a3a);
    } else {
      scene.geometry.addCylinder(i, x(random), y(random), 0, 0.25 + 0.15 * unit(random), 1.7 + 0.2 * unit(random),
                                 0xd04040);
    }
  }
  scene.geometry.buildIndex();
  std::vector<int> near;
  while (scene.cameras.size() < 16) {
    const double cx = x(random), cy = y(random);
    near.clear();
    scene.geometry.solidsNear(cx, cy, 0.5, near);
    bool clear = true;
    for (int s : near) clear = clear && footprintDistance(scene.geometry.solids()[s], cx, cy) > 0.4;
    if (!clear) continue;
    Camera camera;
    camera.pose = {cx, cy, 1.6, angle(random), -15 + 30 * unit(random)};
    camera.intrinsics = {90, image_width, image_height, 20};
    scene.cameras.push_back(camera);
  }
  return scene;
}

// CPU time of this thread [s]: the figure does not depend on what else the
// machine runs.
double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

// Frames per CPU second rendering for about `seconds` (at least min_frames).
double framesPerSecond(const BenchScene& scene, RenderMethod method, double seconds, int min_frames,
                       bool encode, int fixed_frames) {
  RayCaster caster;
  RenderedFrame frame;
  CameraMessages messages, packed;
  FrameCompressor compressor;
  std::vector<std::string> ids(scene.geometry.objectCount(), "object");
  caster.render(scene.geometry, scene.cameras[0], frame, method);  // warm up buffers
  const double start = threadSeconds();
  int frames = 0;
  double elapsed = 0;
  while (fixed_frames > 0 ? frames < fixed_frames : (frames < min_frames || elapsed < seconds)) {
    caster.render(scene.geometry, scene.cameras[frames % scene.cameras.size()], frame, method);
    if (encode) {
      encodeCameraMessages(frame, 0, frames, ids, messages);
      compressor.compress(messages, packed);
    }
    ++frames;
    elapsed = threadSeconds() - start;
  }
  return frames / elapsed;
}

// Frames per wall-clock second on `threads` threads (their CPU time would hide the gain).
double wallFramesPerSecond(const BenchScene& scene, int threads, double seconds) {
  RayCaster caster;
  caster.setThreads(threads);
  RenderedFrame frame;
  caster.render(scene.geometry, scene.cameras[0], frame);
  const auto start = std::chrono::steady_clock::now();
  int frames = 0;
  double elapsed = 0;
  while (frames < 3 || elapsed < seconds) {
    caster.render(scene.geometry, scene.cameras[frames % scene.cameras.size()], frame);
    ++frames;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return frames / elapsed;
}

struct Options {
  std::vector<int> object_counts{10, 30, 100, 1000};
  double seconds = 0.5;            // CPU time per measurement
  double width = 60, height = 40;  // the yard [m]
  uint64_t seed = 1;
  bool skip_brute_force = false;
  int fixed_frames = 0;  // > 0: exactly this many frames per measurement
  std::string packing_scenario = std::string(BEFT_SOURCE_DIR) + "/scenarios/yard.xml";
  int packing_ticks = 300;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Benchmarks the RGBD camera's ray caster: frames per second of CPU time on one core for 160x120 and 640x480 images "
      "over random scenes (walls, crates, persons in a yard), for each render method: projection (used by the "
      "world), grid traversal, and brute force (every object for every ray) as the baseline; the last column "
      "is projection over brute force. Another table times a whole world frame: render, the three "
      "CAMERA_* messages and their compression. The last compares the ways to compress a frame on a "
      "scenario's own frames.",
      "beft-bench-camera");
  app.add_option("--objects", o.object_counts, "object counts to test")->capture_default_str()->delimiter(',');
  app.add_option("--seconds", o.seconds, "CPU time per measurement [s]")->capture_default_str()->check(
      CLI::PositiveNumber);
  app.add_option("--world", o.width, "yard width [m] (height is 2/3 of it)")->capture_default_str()->check(
      CLI::PositiveNumber);
  app.add_option("--seed", o.seed, "random scene seed")->capture_default_str();
  app.add_flag("--no-brute-force", o.skip_brute_force, "skip the slow baseline");
  app.add_option("--packing-scenario", o.packing_scenario, "scenario whose frames the compression table uses")
      ->capture_default_str()
      ->check(CLI::ExistingFile);
  app.add_option("--packing-ticks", o.packing_ticks, "ticks of it the compression table uses")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--frames", o.fixed_frames, "render exactly this many frames per measurement instead (for profilers)")
      ->check(CLI::PositiveNumber);
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  o.height = o.width * 2.0 / 3.0;
  for (int count : o.object_counts) {
    if (count < 0) {
      std::fprintf(stderr, "beft-bench-camera: --objects must be >= 0\n");
      return 2;
    }
  }
  return std::nullopt;
}

// Render methods against each other, per object count and image size.
void compareMethods(const Options& o) {
  std::printf("RGBD camera ray caster, frames per second of CPU time on one core; yard %.0f x %.0f m, range 20 m, fov 90 deg, 16 poses cycled\n",
              o.width, o.height);
  std::printf("%8s %9s %12s %12s %12s %10s\n", "objects", "image", "projection", "grid", "brute-force",
              "speed-up");
  const int sizes[2][2] = {{160, 120}, {640, 480}};
  for (int count : o.object_counts) {
    for (const auto& size : sizes) {
      const BenchScene scene = randomScene(count, o.width, o.height, size[0], size[1], o.seed);
      const double projection = framesPerSecond(scene, RenderMethod::Projection, o.seconds, 3, false, o.fixed_frames);
      const double grid = framesPerSecond(scene, RenderMethod::GridTraversal, o.seconds, 3, false, o.fixed_frames);
      char resolution[32];
      std::snprintf(resolution, sizeof(resolution), "%dx%d", size[0], size[1]);
      if (o.skip_brute_force) {
        std::printf("%8d %9s %10.1f/s %10.1f/s %12s %10s\n", count, resolution, projection, grid, "-", "-");
      } else {
        const double brute = framesPerSecond(scene, RenderMethod::BruteForce, o.seconds, 1, false, o.fixed_frames);
        std::printf("%8d %9s %10.1f/s %10.1f/s %10.2f/s %9.1fx\n", count, resolution, projection, grid, brute,
                    projection / brute);
      }
      std::fflush(stdout);
    }
  }
}

// A whole camera frame as the world publishes it.
void timeWorldFrames(const Options& o) {
  std::printf(
      "\nWhole camera frame as the world publishes it (projection render + 3 messages, compressed), 160x120:\n");
  for (int count : o.object_counts) {
    const BenchScene scene = randomScene(count, o.width, o.height, 160, 120, o.seed);
    std::printf("%8d objects: %10.1f frames/s\n", count,
                framesPerSecond(scene, RenderMethod::Projection, o.seconds, 3, true, o.fixed_frames));
  }
}

// One and two render threads, alternately.
void compareThreads(const Options& o) {
  std::printf("\nProjection render over threads (frames per wall-clock second, 1 and 2 threads alternately;\n"
              "the ratio is what the world gains when a second core is free), 160x120:\n");
  for (int count : o.object_counts) {
    const BenchScene scene = randomScene(count, o.width, o.height, 160, 120, o.seed);
    double best[2] = {0, 0};
    for (int round = 0; round < 3; ++round)
      for (int threads = 1; threads <= 2; ++threads)
        best[threads - 1] = std::max(best[threads - 1], wallFramesPerSecond(scene, threads, o.seconds / 3));
    std::printf("%8d objects: %10.1f/s on 1 thread, %10.1f/s on 2, ratio %.2f\n", count, best[0], best[1],
                best[1] / best[0]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  compareMethods(options);
  timeWorldFrames(options);
  compareThreads(options);
  beft::bench::printPackingTable(options.packing_scenario, options.packing_ticks);
  return 0;
}
