#include "lib/hearing/trials/room_trials.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

#include "lib/hearing/late_reverb.hpp"

namespace beft::hearing::trials {

namespace {

constexpr double kDistance = 1.5;  // talker to head [m], as the Surrey BRIRs
constexpr double kWall = 0.3;      // wall thickness [m]

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::vector<ReflectingBox> shoeboxWalls(double absorption) {
  const double t = kWall;
  return {
      {-t / 2, kRoomY / 2, 0, t, kRoomY + 2 * t, 0, kRoomZ + t, absorption, 1},
      {kRoomX + t / 2, kRoomY / 2, 0, t, kRoomY + 2 * t, 0, kRoomZ + t, absorption, 2},
      {kRoomX / 2, -t / 2, 0, kRoomX + 2 * t, t, 0, kRoomZ + t, absorption, 3},
      {kRoomX / 2, kRoomY + t / 2, 0, kRoomX + 2 * t, t, 0, kRoomZ + t, absorption, 4},
      {kRoomX / 2, kRoomY / 2, 0, kRoomX + 2 * t, kRoomY + 2 * t, kRoomZ, kRoomZ + t, absorption, 5},
  };
}

Eigen::Vector3d talkerAt(double azimuth_deg) {
  const double a = azimuth_deg * M_PI / 180;
  return trialListener() + kDistance * Eigen::Vector3d(std::cos(a), std::sin(a), 0);
}

// The nearest of peaks [0, count) to a direction [deg]; 180 if none.
double nearestPeak(const BlockLocalisation& found, int count, double azimuth_deg, double* peak = nullptr) {
  double best = 180;
  for (int p = 0; p < std::min<int>(count, static_cast<int>(found.peaks.size())); ++p) {
    const double d = angularDistance(found.peaks[static_cast<std::size_t>(p)].azimuth_deg, azimuth_deg);
    if (d < best) {
      best = d;
      if (peak != nullptr) *peak = found.peaks[static_cast<std::size_t>(p)].azimuth_deg;
    }
  }
  return best;
}

// Whether a talker was heard at its mirror image: none of the peaks within
// 10 degrees of it, and one within 10 degrees of its mirror image that no
// other talker accounts for (none of them within 10 degrees of that peak).
// A peak of another talker who happens to stand near the mirror image is
// that talker found, not this one confused; a talker missed with no peak
// near its mirror image is missed, not confused.
bool confused(const BlockLocalisation& found, int count, double azimuth_deg, const std::vector<double>& talkers_deg) {
  if (nearestPeak(found, count, azimuth_deg) <= 10) return false;
  const double mirror = frontBackMirror(azimuth_deg);
  for (int p = 0; p < std::min<int>(count, static_cast<int>(found.peaks.size())); ++p) {
    const double peak = found.peaks[static_cast<std::size_t>(p)].azimuth_deg;
    if (angularDistance(peak, mirror) > 10) continue;
    if (std::none_of(talkers_deg.begin(), talkers_deg.end(),
                     [&](double other) { return other != azimuth_deg && angularDistance(peak, other) <= 10; }))
      return true;
  }
  return false;
}

// Whole-degree azimuths at least 30 degrees apart.
std::vector<double> drawAzimuths(int count, std::mt19937_64& random) {
  std::uniform_int_distribution<int> degree(0, 359);
  std::vector<double> azimuths;
  while (static_cast<int>(azimuths.size()) < count) {
    const double a = degree(random);
    if (std::all_of(azimuths.begin(), azimuths.end(), [&](double b) { return angularDistance(a, b) >= 30; }))
      azimuths.push_back(a);
  }
  return azimuths;
}

}  // namespace

Eigen::Vector3d trialListener() { return {6, 5, 1.6}; }

TrialRoom trialRoom(double t60_s, const HrirSet& hrirs, int reflection_order) {
  TrialRoom room;
  room.t60_s = t60_s;
  if (t60_s <= 0) return room;
  const double volume = kRoomX * kRoomY * kRoomZ;
  const double surface = 2 * (kRoomX * kRoomY + kRoomX * kRoomZ + kRoomY * kRoomZ);
  // Eyring: T60 = 0.161 V / (-S ln(1 - a)), solved for a.
  const double absorption = 1 - std::exp(-0.161 * volume / (surface * t60_s));
  RoomSettings settings;
  settings.reflection_order = reflection_order;
  settings.ground = true;
  settings.ground_absorption = absorption;
  settings.t60_s = t60_s;
  settings.volume_m3 = volume;
  settings.seed = 7;
  room.model = std::make_unique<RoomModel>(shoeboxWalls(absorption), settings, hrirs, hrirs.sampleRate());
  return room;
}

RoomTrials::RoomTrials(const BinauralRenderer& renderer, BlockLocaliser localiser, const std::string& sounds_dir)
    : renderer_(renderer), localiser_(std::move(localiser)) {
  for (const char* name : {"talk", "help", "voice_radio"}) {
    SourceSignal signal;
    signal.samples = scenarioSound(name, 0.1f, sounds_dir);
    signals_.push_back(std::move(signal));
  }
}

int64_t RoomTrials::momentAllSpeak(const std::vector<int>& talkers, int sources, int turns, int blocks_per_pose,
                                   std::mt19937_64& random) const {
  std::uniform_int_distribution<int64_t> start(static_cast<int64_t>(2 * kRate), static_cast<int64_t>(60 * kRate));
  const int listening = blocks_per_pose * kBlock;
  int64_t first = start(random);
  for (int attempt = 0; attempt < 200; ++attempt, first = start(random)) {
    bool speaking = true;
    for (int s = 0; s < sources; ++s) {
      const auto& signal = signals_[static_cast<std::size_t>(talkers[static_cast<std::size_t>(s)])].samples;
      for (int pose = 0; pose <= turns; ++pose)
        speaking = speaking && loopedRms(signal, static_cast<long>(first + pose * listening), listening) > 0.05;
    }
    if (speaking) break;
  }
  return first;
}

std::vector<StereoBlock> RoomTrials::hearPoses(BlockRequest request, int64_t first, int turns,
                                               int blocks_per_pose) const {
  std::vector<StereoBlock> poses(static_cast<std::size_t>(turns + 1));
  for (int pose = 0; pose <= turns; ++pose) {
    StereoBlock& heard = poses[static_cast<std::size_t>(pose)];
    request.previous.yaw_deg = request.current.yaw_deg = pose * kDefaultResolvingTurnDeg;
    for (int b = 0; b < blocks_per_pose; ++b) {
      request.first_sample = first + (pose * blocks_per_pose + b) * kBlock;
      const StereoBlock block = renderer_.render(request);
      heard.left.insert(heard.left.end(), block.left.begin(), block.left.end());
      heard.right.insert(heard.right.end(), block.right.begin(), block.right.end());
    }
  }
  return poses;
}

RoomFigures RoomTrials::run(const TrialRoom& room, int sources, int trials, uint64_t seed, int turns,
                            int blocks_per_pose) {
  if (sources < 1 || sources > static_cast<int>(signals_.size()))
    throw std::invalid_argument("RoomTrials: 1 to 3 talkers");
  if (turns < 1 || turns > 8) throw std::invalid_argument("RoomTrials: 1 to 8 head turns");
  if (blocks_per_pose < 1 || blocks_per_pose > 10) throw std::invalid_argument("RoomTrials: 1 to 10 blocks per pose");
  RoomFigures figures;
  figures.t60_s = room.t60_s;
  figures.sources = sources;
  figures.trials = trials;
  figures.turns = turns;
  figures.blocks_per_pose = blocks_per_pose;
  std::mt19937_64 random(seed);
  std::vector<double> errors;
  int within = 0, counted = 0, static_confusions = 0, turned_confusions = 0;
  const double turn = kDefaultResolvingTurnDeg;
  for (int trial = 0; trial < trials; ++trial) {
    const std::vector<double> azimuths = drawAzimuths(sources, random);
    std::vector<int> talkers(signals_.size());
    std::iota(talkers.begin(), talkers.end(), 0);
    std::shuffle(talkers.begin(), talkers.end(), random);
    if (sources == 1) talkers[0] = trial % static_cast<int>(signals_.size());
    const int64_t first = momentAllSpeak(talkers, sources, turns, blocks_per_pose, random);
    BlockRequest request;
    request.num_samples = kBlock;
    request.noise_rms = 1e-4;
    request.noise_seed = seed * 1000 + static_cast<uint64_t>(trial);
    request.room = room.model.get();
    request.previous.centre = request.current.centre = trialListener();
    for (int s = 0; s < sources; ++s)
      request.sources.push_back({&signals_[static_cast<std::size_t>(talkers[static_cast<std::size_t>(s)])],
                                 talkerAt(azimuths[static_cast<std::size_t>(s)]), 1.0, 0.0});
    const std::vector<StereoBlock> heard_poses = hearPoses(request, first, turns, blocks_per_pose);
    const StereoBlock& before = heard_poses.front();
    std::vector<EarBlock> pooled;
    for (int pose = 0; pose <= turns; ++pose)
      pooled.push_back(EarBlock{heard_poses[static_cast<std::size_t>(pose)].left,
                                heard_poses[static_cast<std::size_t>(pose)].right, (turns - pose) * turn});
    const BlockLocalisation heard_before = localiser_.localise(before.left, before.right);
    const BlockLocalisation heard_after = localiser_.localise(pooled);
    std::vector<double> azimuths_now;
    for (double azimuth : azimuths) azimuths_now.push_back(wrapDegrees(azimuth - turns * turn));
    for (double azimuth : azimuths) {
      const double now = wrapDegrees(azimuth - turns * turn);
      const double error = nearestPeak(heard_after, sources, now);
      errors.push_back(error);
      within += error <= 5;
      if (angularDistance(azimuth, frontBackMirror(azimuth)) > 20 && angularDistance(now, frontBackMirror(now)) > 20) {
        ++counted;
        static_confusions += confused(heard_before, sources, azimuth, azimuths);
        turned_confusions += confused(heard_after, sources, now, azimuths_now);
      }
    }
  }
  figures.within_5deg = errors.empty() ? 0 : static_cast<double>(within) / errors.size();
  figures.median_error_deg = median(errors);
  if (counted > 0) {
    figures.front_back_static = static_cast<double>(static_confusions) / counted;
    figures.front_back_after_turn = static_cast<double>(turned_confusions) / counted;
  }
  if (room.model) {
    const StereoBlock response = roomImpulseResponse(renderer_, room, room.t60_s + 0.3);
    figures.t60_measured_s = schroederT60(response.left, response.right, kRate);
    const int direct_end = static_cast<int>((kDistance / BinauralRenderer::kSpeedOfSound + 0.0025) * kRate);
    figures.drr_db = directToReverberantDb(response.left, response.right, direct_end);
  }
  return figures;
}

StereoBlock roomImpulseResponse(const BinauralRenderer& renderer, const TrialRoom& room, double seconds) {
  SourceSignal click;
  click.samples.assign(static_cast<std::size_t>((seconds + 2) * kRate), 0.0f);
  click.samples[0] = 1.0f;
  BlockRequest request;
  request.first_sample = 0;
  request.num_samples = static_cast<int>(seconds * kRate);
  request.noise_rms = 0;
  request.room = room.model.get();
  request.previous.centre = request.current.centre = trialListener();
  request.sources.push_back({&click, talkerAt(0), 1.0, 0.0});
  return renderer.render(request);
}

}  // namespace beft::hearing::trials
