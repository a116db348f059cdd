// beft-render: a recorded run, frame by frame (./beft replay LOG --to DIR|FILE.mp4):
// the top-down view (world, robot and its path, the obstacle map as known at
// that tick, hypotheses) next to the camera image of the same tick.
#include <CLI/CLI.hpp>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <string>

#include <beft/camera_frame_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <lcm/lcm-cpp.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "lib/common/command_line.hpp"
#include "lib/common/channels.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/report/drawing.hpp"
#include "lib/camera/frame_decoding.hpp"
#include "lib/report/map_picture.hpp"
#include "lib/wire/obstacle_map_changes.hpp"
#include "lib/wire/run_identity.hpp"
#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"

namespace {

using namespace beft;

// The per-tick pictures the run record does not keep: camera colour images
// (as logged, compressed: unpacked when drawn) and obstacle maps, by tick.
struct TickImages {
  std::map<int64_t, beft::camera_frame_t> camera;
  std::map<int64_t, beft::obstacle_map_t> maps;  // keyframes (every tick in logs from before the changes)
  std::map<int64_t, beft::obstacle_map_changes_t> map_changes;
};

// Damaged records are skipped (the run record reports them). The run's
// channels carry its id: those of the log's run are read.
TickImages readTickImages(const std::string& path) {
  const int64_t run = wire::runId() != 0 ? wire::runId() : wire::runOfLog(path);
  wire::LogReader log(path);
  TickImages images;
  wire::LogEvent event;
  while (log.nextOfRun(event, run)) {
    if (event.channel == channels::kCameraColor) {
      beft::camera_frame_t frame{};
      if (wire::guardedDecode(event.data.data(), event.data.size(), frame).ok() &&
          frame.encoding == beft::camera_frame_t::ENCODING_RGB8)
        images.camera[frame.tick] = std::move(frame);
    } else if (event.channel == channels::kObstacleMap) {
      beft::obstacle_map_t map{};
      if (wire::guardedDecode(event.data.data(), event.data.size(), map).ok()) images.maps[map.tick] = std::move(map);
    } else if (event.channel == channels::kObstacleMapChanges) {
      beft::obstacle_map_changes_t changes{};
      if (wire::guardedDecode(event.data.data(), event.data.size(), changes).ok())
        images.map_changes[changes.tick] = std::move(changes);
    }
  }
  return images;
}

// The record as it stood at the end of tick `tick`.
report::RunRecord recordUpTo(const report::RunRecord& full, int64_t tick, double t, const TickImages& images) {
  report::RunRecord part = full;
  part.robot.clear();
  for (const auto& sample : full.robot)
    if (sample.tick <= tick) part.robot.push_back(sample);
  auto keepUntil = [t](auto& samples) {
    samples.erase(std::remove_if(samples.begin(), samples.end(), [t](const auto& s) { return s.t > t + 1e-9; }),
                  samples.end());
  };
  keepUntil(part.hypotheses);
  keepUntil(part.weights);
  keepUntil(part.tasks);
  part.obstacle_map.reset();
  // The map of the tick: its keyframe with its changes, or the newest map before.
  auto changes_it = images.map_changes.upper_bound(tick);
  auto map_it = images.maps.upper_bound(tick);
  try {
    if (changes_it != images.map_changes.begin()) {
      const auto& changes = std::prev(changes_it)->second;
      const auto keyframe = images.maps.find(changes.keyframe_tick);
      if (keyframe != images.maps.end()) {
        part.obstacle_map = keyframe->second.tick == changes.tick
                                ? planners::decodeObstacleMap(keyframe->second)
                                : *planners::ObstacleMapAssembler().mapOf(keyframe->second, &changes);
        return part;
      }
    }
    if (map_it != images.maps.begin()) part.obstacle_map = planners::decodeObstacleMap(std::prev(map_it)->second);
  } catch (const std::exception&) {
  }
  return part;
}

cv::Mat cameraPanel(const TickImages& images, int64_t tick, int height) {
  const int width = height * 4 / 3;
  cv::Mat panel(height, width, CV_8UC3, cv::Scalar(40, 40, 40));
  auto it = images.camera.find(tick);
  if (it == images.camera.end()) {
    report::draw::text(panel, "no camera image for this tick", {20, height / 2}, 0.6, report::draw::kWhite);
    return panel;
  }
  beft::camera_frame_t frame;
  std::string why;
  if (!camera::decodeCameraFrame(it->second, frame, &why)) {
    report::draw::text(panel, "camera image refused: " + why, {20, height / 2}, 0.5, report::draw::kWhite);
    return panel;
  }
  cv::Mat rgb(frame.height, frame.width, CV_8UC3, frame.data.data());
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  cv::resize(bgr, panel, panel.size(), 0, 0, cv::INTER_NEAREST);
  char caption[96];
  std::snprintf(caption, sizeof(caption), "camera  tick %lld  heading %.0f deg", static_cast<long long>(tick),
                frame.cam_yaw);
  report::draw::labelBox(panel, caption, {10, 24}, 0.55, report::draw::kBlack, report::draw::kWhite);
  return panel;
}

struct Options {
  std::string log_path, to;  // the run's log; a folder, or FILE.mp4 / FILE.avi
  int every = 5;
  double fps = 10;
  bool video() const {
    return to.size() > 4 && (to.substr(to.size() - 4) == ".mp4" || to.substr(to.size() - 4) == ".avi");
  }
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Renders a recorded run frame by frame: the top-down view (world, robot path, the obstacle map known at "
      "that tick, hypotheses) next to the camera image. Writes PNGs into a folder, or a video when the target "
      "ends in .mp4 or .avi (OpenCV VideoWriter). Needs no live system.",
      "beft-render");
  app.add_option("log", o.log_path, "the run's LCM log")->required()->check(CLI::ExistingFile);
  app.add_option("--to", o.to, "folder for frame_NNNNN.png, or FILE.mp4 / FILE.avi")->required();
  app.add_option("--every", o.every, "render every N-th tick")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--fps", o.fps, "video frame rate")->capture_default_str()->check(CLI::PositiveNumber);
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// Where the frames go: a video writer opened at the first frame, or PNGs in a folder.
class FrameSink {
 public:
  explicit FrameSink(const Options& o) : o_(o) {}
  bool prepare() {
    if (o_.video()) return true;
    mkdir(o_.to.c_str(), 0755);
    struct stat info {};
    if (stat(o_.to.c_str(), &info) == 0 && S_ISDIR(info.st_mode)) return true;
    std::fprintf(stderr, "[render] error: cannot create the folder %s\n", o_.to.c_str());
    return false;
  }
  bool write(const cv::Mat& frame, int64_t tick) {
    if (o_.video()) {
      if (!writer_.isOpened()) {
        const int fourcc = o_.to.substr(o_.to.size() - 4) == ".avi" ? cv::VideoWriter::fourcc('M', 'J', 'P', 'G')
                                                                     : cv::VideoWriter::fourcc('m', 'p', '4', 'v');
        if (!writer_.open(o_.to, fourcc, o_.fps, frame.size())) {
          std::fprintf(stderr, "[render] error: cannot open a video writer for %s\n", o_.to.c_str());
          return false;
        }
      }
      writer_.write(frame);
      return true;
    }
    char name[64];
    std::snprintf(name, sizeof(name), "/frame_%05lld.png", static_cast<long long>(tick));
    if (cv::imwrite(o_.to + name, frame)) return true;
    std::fprintf(stderr, "[render] error: cannot write %s%s\n", o_.to.c_str(), name);
    return false;
  }

 private:
  const Options& o_;
  cv::VideoWriter writer_;
};

int render(const Options& o) {
  report::RunRecord full;
  try {
    full = report::readRunLog(o.log_path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "[render] error: %s\n", e.what());
    return 1;
  }
  if (full.robot.empty()) {
    std::fprintf(stderr, "[render] error: %s has no ROBOT_STATE: nothing to render\n", o.log_path.c_str());
    return 1;
  }
  const TickImages images = readTickImages(o.log_path);
  FrameSink sink(o);
  if (!sink.prepare()) return 1;
  int frames = 0;
  for (std::size_t i = 0; i < full.robot.size(); i += static_cast<std::size_t>(o.every)) {
    const auto& sample = full.robot[i];
    const auto part = recordUpTo(full, sample.tick, sample.t, images);
    const auto scored = report::scoreRun(part, report::ScoringOptions{});
    cv::Mat top = report::renderMap(part, scored);
    cv::Mat camera = cameraPanel(images, sample.tick, top.rows);
    cv::Mat frame;
    cv::hconcat(top, camera, frame);
    if (!sink.write(frame, sample.tick)) return 1;
    ++frames;
  }
  std::printf("[render] %d frames (every %d ticks) written to %s\n", frames, o.every, o.to.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return render(options);
}
