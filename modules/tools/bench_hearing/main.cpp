// beft-bench-hearing (./beft bench hearing): hearing's figures. The
// renderer's cues of a source at +90 deg (ITD, ILD) and how much faster than
// real time it renders four sources on one core; the localiser's accuracy on
// ear signals through the KEMAR responses (trials/localisation_trials); and
// missions that hear for real (--acoustics binaural) with each heard
// object's position error. Each figure is one entry of figures(): a key, its
// unit, what it measures and how.
#include <time.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "lib/hearing/binaural_cues.hpp"
#include "lib/hearing/binaural_renderer.hpp"
#include "lib/common/command_line.hpp"
#include "lib/hearing/hrir_set.hpp"
#include "lib/hearing/trials/localisation_trials.hpp"
#include "lib/hearing/trials/room_trials.hpp"
#include "lib/common/log.hpp"
#include "lib/common/own_bin_dir.hpp"
#include "lib/common/quiet_child.hpp"

using namespace beft::hearing;

namespace {

constexpr double kRate = 44100;
constexpr int kBlock = 4410;  // one tick, 0.1 s
constexpr double kPi = 3.14159265358979323846;

struct Options {
  std::string hrir_path = HrirSet::kKemarPath;
  bool spherical_head = false;
  double seconds = 2.0;  // CPU time per speed figure
  int single_trials = 360;
  int pair_trials = 100;
  uint64_t seed = 1;
  std::string sounds_dir = trials::scenarioSoundsDir();
  bool missions = true;
  bool rooms = true;
  int room_trials = 300;
  std::vector<double> room_t60s = {0.0, 0.3, 0.6, 0.9};
  std::vector<int> room_turns = {1};
  int room_listen_blocks = trials::kSentenceBlocksPerPose;  // 0.1 s blocks heard at each pose
  bool json = false;
};

// What every figure may use; built once.
struct Bench {
  const Options& options;
  const BinauralRenderer& renderer;
  SourceSignal noise;  // white, 2 s, unit RMS
  trials::OneSourceFigures one_source;
  trials::TwoSourceFigures two_sources;
  double localise_ms_per_block = 0;
};

struct Figure {
  std::string key;
  std::string unit;
  std::string meaning;
  std::function<double(const Bench&)> measure;
};

// CPU time of this thread [s]: the figure does not depend on what else the
// machine runs.
double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

SourceSignal whiteNoise(double seconds, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<float> normal(0, 1);
  SourceSignal signal;
  signal.samples.resize(static_cast<std::size_t>(seconds * kRate));
  for (float& sample : signal.samples) sample = normal(random);
  return signal;
}

Eigen::Vector3d at(double azimuth_deg, double distance) {
  return {distance * std::cos(azimuth_deg * kPi / 180), distance * std::sin(azimuth_deg * kPi / 180), 0};
}

// White noise from +90 deg (the left), 2 m away, head at the origin facing +x; 0.2 s, no sensor noise.
StereoBlock leftSource(const Bench& bench) {
  BlockRequest request;
  request.first_sample = kBlock * 10;
  request.num_samples = 2 * kBlock;
  request.noise_rms = 0;
  request.sources.push_back({&bench.noise, at(90, 2.0), 1.0, 0.0});
  return bench.renderer.render(request);
}

// Four sources at 30, 120, -45 and -160 deg, 1.5 to 6 m, one partly
// occluded; consecutive blocks rendered for about options.seconds of CPU
// time. `moving`: the head turns at 90 deg/s and walks at 0.5 m/s (every
// block cross-fades two poses); otherwise it stands still. In a room, the
// head starts at the trials' listener of the 16 x 12 x 4 m shoebox. Rendered
// audio seconds per CPU second.
double realtimeFactor(const Bench& bench, bool moving, const trials::TrialRoom* room = nullptr) {
  const std::vector<SourceSignal> signals = {whiteNoise(1.3, 1), whiteNoise(1.7, 2), whiteNoise(2.1, 3),
                                             whiteNoise(0.9, 4)};
  BlockRequest request;
  request.num_samples = kBlock;
  request.noise_seed = 5;
  const double azimuths[4] = {30, 120, -45, -160}, distances[4] = {1.5, 3, 4.5, 6}, occlusions[4] = {0, 0.4, 0, 1};
  const Eigen::Vector3d origin = room != nullptr ? trials::trialListener() : Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i)
    request.sources.push_back({&signals[i], origin + at(azimuths[i], distances[i]), 1.0, occlusions[i]});
  if (room != nullptr) request.room = room->model.get();
  StereoBlock out;
  const auto setTick = [&](int64_t tick) {
    request.first_sample = tick * kBlock;
    const double step = moving ? 1.0 : 0.0;
    request.previous.yaw_deg = step * 9.0 * tick;
    request.current.yaw_deg = step * 9.0 * (tick + 1);
    // Back and forth over 2 m, so that a long measurement stays in the room.
    const auto walked = [&](int64_t t) { return step * 0.05 * static_cast<double>(std::abs((t % 80) - 40)); };
    request.previous.centre = origin + Eigen::Vector3d(walked(tick), 0, 0);
    request.current.centre = origin + Eigen::Vector3d(walked(tick + 1), 0, 0);
  };
  setTick(0);
  bench.renderer.render(request, out);  // FFT plans and buffers
  const double start = threadSeconds();
  int64_t blocks = 0;
  double elapsed = 0;
  while (blocks < 5 || elapsed < bench.options.seconds) {
    setTick(blocks + 1);
    bench.renderer.render(request, out);
    ++blocks;
    elapsed = threadSeconds() - start;
  }
  return blocks * (kBlock / kRate) / elapsed;
}

const std::vector<Figure>& figures() {
  static const std::vector<Figure> list = {
      {"itd_90_ms", "ms", "ITD of white noise from +90 deg at 2 m (cross-correlation peak; > 0: left ear first)",
       [](const Bench& b) {
         const StereoBlock ears = leftSource(b);
         return interauralTimeDifferenceMs(ears.left, ears.right, kRate);
       }},
      {"ild_90_db", "dB", "ILD of the same above 4 kHz (> 0: left ear louder)",
       [](const Bench& b) {
         const StereoBlock ears = leftSource(b);
         return interauralLevelDifferenceDb(ears.left, ears.right, kRate, 4000);
       }},
      {"median_azimuth_error_deg", "deg",
       "one source 2 m away (white, pink, two voices), after one head turn: median azimuth error",
       [](const Bench& b) { return b.one_source.median_error_after_turn_deg; }},
      {"front_back_static", "", "share of those trials confused front for back without turning",
       [](const Bench& b) { return b.one_source.front_back_static; }},
      {"front_back_after_turn", "", "the same after one head turn of 20 deg (target < 0.05)",
       [](const Bench& b) { return b.one_source.front_back_after_turn; }},
      {"two_sources_within_10deg", "",
       "two different sounds >= 30 deg apart: share found within 10 deg after the turn (target >= 0.85)",
       [](const Bench& b) { return b.two_sources.found_after_turn; }},
      {"localise_ms_per_block", "ms", "the localiser's CPU time per 0.1 s block",
       [](const Bench& b) { return b.localise_ms_per_block; }},
      {"render_realtime_factor_4_sources", "x",
       "4 sources, head turning 90 deg/s and walking 0.5 m/s: audio rendered per CPU second on one core",
       [](const Bench& b) { return realtimeFactor(b, true); }},
      {"render_realtime_factor_4_sources_static", "x", "the same with the head standing still",
       [](const Bench& b) { return realtimeFactor(b, false); }},
      {"render_realtime_factor_4_sources_reverberant", "x",
       "the moving head's 4 sources in a 16 x 12 x 4 m room: image sources to order 2 and a 0.6 s tail",
       [](const Bench& b) {
         const trials::TrialRoom room = trials::trialRoom(0.6, b.renderer.hrirs(), 2);
         return realtimeFactor(b, true, &room);
       }},
  };
  return list;
}

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Benchmarks hearing. The renderer: the cues of a white-noise source at +90 deg (ITD, ILD above 4 kHz) and how "
      "many times faster than real time it renders 4 sources in 0.1 s blocks on one core (CPU time of this thread). "
      "The localiser, on sources 2 m away convolved with the KEMAR responses of the simulation and localised "
      "against templates of the MIT KEMAR (a different head), each trial a block with the head still and one "
      "turned by 20 deg: the median azimuth error, front-back confusions without and with the turn, two "
      "simultaneous sources found within 10 deg, CPU per block. Then yard, peek and decoy run with --acoustics "
      "binaural, and each heard object's position error is printed. Human-readable by default, one JSON object "
      "with --json.",
      "beft-bench-hearing");
  app.add_option("--hrir", o.hrir_path, "HRIR set (WAV, the SSR's layout); falls back to the spherical head")
      ->capture_default_str();
  app.add_flag("--spherical-head", o.spherical_head, "render with the spherical-head model instead of the HRIR file");
  app.add_option("--seconds", o.seconds, "CPU time per speed figure [s]")->capture_default_str()->check(
      CLI::PositiveNumber);
  app.add_option("--trials", o.single_trials, "one-source trials")->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--pairs", o.pair_trials, "two-source trials")->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--seed", o.seed, "seed of the trials")->capture_default_str();
  app.add_option("--sounds", o.sounds_dir, "folder of the scenario sounds")->capture_default_str()->check(
      CLI::ExistingDirectory);
  app.add_flag("!--no-missions", o.missions, "skip the missions (yard, peek, decoy with --acoustics binaural)");
  app.add_flag("!--no-rooms", o.rooms, "skip the localiser's trials in rooms");
  app.add_option("--room-trials", o.room_trials, "trials per room and number of talkers")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000));
  app.add_option("--room-t60", o.room_t60s, "the rooms' T60s [s] (0: the free field)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3.0));
  app.add_option("--room-turns", o.room_turns, "head turns of 20 deg heard in the rooms (1: the protocol's one)")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  app.add_option("--room-listen-blocks", o.room_listen_blocks,
                 "consecutive 0.1 s blocks heard at each pose of the head in the rooms (1: one block, as the audio expert localises each)")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  app.add_flag("--json", o.json, "print one JSON object of the figures");
  return beft::parseCommandLine(app, argc, argv);
}

// A mission heard for real: did it succeed, and how far off was each heard object.
nlohmann::json hearingMission(const std::string& scenario) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("beft_bench_hearing_" + std::to_string(getpid()) + "_" + scenario);
  const int exit_code = beft::runQuietly({beft::ownBinDir() + "/beft-run",
                                          std::string(BEFT_SOURCE_DIR) + "/scenarios/" + scenario + ".xml",
                                          "--acoustics", "binaural", "--out", dir.string()});
  nlohmann::json mission = {{"scenario", scenario}, {"exit_code", exit_code}};
  try {
    std::ifstream in(dir / "report.json");
    const nlohmann::json report = nlohmann::json::parse(in);
    mission["persons"] = report.at("persons");
    mission["victims"] = report.at("victims").size();
    mission["falsified"] = nlohmann::json::array();
    for (const auto& f : report.at("falsified")) mission["falsified"].push_back(f.at("object"));
    mission["collisions"] = report.at("collisions");
    mission["heard"] = nlohmann::json::array();
    for (const auto& h : report.at("heard"))
      mission["heard"].push_back({{"object", h.at("object")}, {"error_m", h.at("error_m")}});
  } catch (const std::exception& e) {
    mission["error"] = std::string("no report: ") + e.what();
  }
  std::error_code ignored;
  fs::remove_all(dir, ignored);
  return mission;
}

void printMission(const nlohmann::json& mission) {
  if (mission.contains("error")) {
    std::printf("  %-8s failed (exit %d, %s)\n", mission["scenario"].get<std::string>().c_str(),
                mission["exit_code"].get<int>(), mission["error"].get<std::string>().c_str());
    return;
  }
  std::printf("  %-8s persons found %d/%d, falsified %s, collisions %d; heard:",
              mission["scenario"].get<std::string>().c_str(), mission["victims"].get<int>(),
              mission["persons"].get<int>(), mission["falsified"].empty() ? "none" : mission["falsified"].dump().c_str(),
              mission["collisions"].get<int>());
  for (const auto& h : mission["heard"])
    std::printf(" %s %.2f m", h["object"].get<std::string>().c_str(), h["error_m"].get<double>());
  std::printf("\n");
}

HrirSet loadHrirs(const Options& options) {
  return options.spherical_head
             ? HrirSet::sphericalHead(kRate)
             : HrirSet::loadDefault([](const std::string& m) { beft::log::warn(m); }, options.hrir_path);
}

// Every figure of figures(), measured in turn (and printed as it comes
// unless --json), in a report that also names the HRIR set.
nlohmann::json measureFigures(const Options& options, const HrirSet& hrirs) {
  const BinauralRenderer renderer(hrirs, kRate);
  Bench bench{options, renderer, whiteNoise(2.0, 7), {}, {}, 0};
  trials::LocalisationTrials localisation(BlockLocaliser(InterauralTemplates::fromSofa()), options.sounds_dir);
  bench.one_source = localisation.oneSource(options.single_trials, options.seed);
  bench.two_sources = localisation.twoSources(options.pair_trials, options.seed + 1);
  bench.localise_ms_per_block = localisation.localiseMsPerBlock();

  nlohmann::json report;
  report["hrir_set"] = hrirs.name();
  if (!options.json) std::printf("HRIR set: %s\n", hrirs.name().c_str());
  for (const Figure& figure : figures()) {
    const double value = figure.measure(bench);
    report[figure.key] = value;
    if (!options.json) {
      std::printf("%-42s %9.3f %-3s %s\n", figure.key.c_str(), value, figure.unit.c_str(), figure.meaning.c_str());
      std::fflush(stdout);
    }
  }
  return report;
}

// The localiser in rooms (trials/room_trials.hpp): one entry per T60 and
// number of talkers, added to the report as "rooms" (and printed unless --json).
void addRooms(const Options& options, const BinauralRenderer& renderer, nlohmann::json& report) {
  report["rooms"] = nlohmann::json::array();
  if (!options.json)
    std::printf("rooms (16 x 12 x 4 m shoebox, talkers 1.5 m away over 360 deg, after one head turn of 20 deg or "
                "more, listening %.1f s at each pose; the free field with the localiser's defaults, the rooms with "
                "LocaliserConfig::reverberant()):\n"
                "  %6s %8s %7s %5s %7s %9s %8s %8s %8s\n",
                options.room_listen_blocks * trials::kBlock / trials::kRate, "T60", "measured", "DRR dB", "turns",
                "talkers", "within 5", "median", "fb still", "fb turn");
  // The free field with the localiser's defaults, the rooms with its reverberant profile (the place is known).
  trials::RoomTrials free_field(renderer, BlockLocaliser(InterauralTemplates::fromSofa()), options.sounds_dir);
  trials::RoomTrials rooms(renderer, BlockLocaliser(InterauralTemplates::fromSofa(), LocaliserConfig::reverberant()),
                           options.sounds_dir);
  for (int turns : options.room_turns)
    for (double t60 : options.room_t60s) {
      const trials::TrialRoom room = trials::trialRoom(t60, renderer.hrirs(), 2);
      for (int talkers = 1; talkers <= 3; ++talkers) {
        trials::RoomTrials& trials = t60 > 0 ? rooms : free_field;
        const trials::RoomFigures f =
            trials.run(room, talkers, options.room_trials, options.seed + 100 * talkers, turns,
                       options.room_listen_blocks);
        nlohmann::json entry = {{"t60_s", f.t60_s},
                                {"t60_measured_s", f.t60_measured_s},
                                {"drr_db", f.drr_db ? nlohmann::json(*f.drr_db) : nlohmann::json(nullptr)},
                                {"localiser", t60 > 0 ? "reverberant" : "default"},
                                {"turns", f.turns},
                                {"listening_s", f.blocks_per_pose * trials::kBlock / trials::kRate},
                                {"sources", f.sources},
                                {"trials", f.trials},
                                {"within_5deg", f.within_5deg},
                                {"median_error_deg", f.median_error_deg},
                                {"front_back_static", f.front_back_static},
                                {"front_back_after_turn", f.front_back_after_turn}};
        report["rooms"].push_back(entry);
        if (!options.json) {
          std::printf("  %6.1f %8.3f %7s %5d %7d %9.3f %8.2f %8.3f %8.3f\n", f.t60_s, f.t60_measured_s,
                      f.drr_db ? std::to_string(*f.drr_db).substr(0, 5).c_str() : "-", f.turns, f.sources,
                      f.within_5deg, f.median_error_deg, f.front_back_static, f.front_back_after_turn);
          std::fflush(stdout);
        }
      }
    }
}

// The missions that hear for real, added to the report (and printed unless --json).
void addHearingMissions(const Options& options, nlohmann::json& report) {
  report["missions"] = nlohmann::json::array();
  if (!options.json) std::printf("missions with --acoustics binaural (each heard object's last estimate):\n");
  for (const char* scenario : {"yard", "peek", "decoy"}) {
    report["missions"].push_back(hearingMission(scenario));
    if (!options.json) printMission(report["missions"].back());
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  beft::log::setProcessName("bench-hearing");
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  try {
    const HrirSet hrirs = loadHrirs(options);
    if (hrirs.sampleRate() != kRate) {
      std::fprintf(stderr, "beft-bench-hearing: %s is at %.0f Hz; the benchmark renders at %.0f Hz\n",
                   hrirs.name().c_str(), hrirs.sampleRate(), kRate);
      return 1;
    }
    nlohmann::json report = measureFigures(options, hrirs);
    if (options.rooms) addRooms(options, BinauralRenderer(hrirs, kRate), report);
    if (options.missions) addHearingMissions(options, report);
    if (options.json) std::printf("%s\n", report.dump(2).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-bench-hearing: %s\n", e.what());
    return 1;
  }
  return 0;
}
