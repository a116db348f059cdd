// beft-bench-hearing (./beft bench hearing): how well the localiser finds
// sounds in ear signals rendered through the KEMAR responses, against its
// templates from the MIT KEMAR, and what a block costs it.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "block_localiser.hpp"
#include "command_line.hpp"
#include "ear_scene.hpp"

using namespace beft::hearing;
using beft::bench::kBlock;
using beft::bench::KemarEars;
using beft::bench::PlacedSound;

namespace {

struct Options {
  int single_trials = 360;  // one source at each whole degree
  int pair_trials = 100;
  uint64_t seed = 1;
  std::string sounds_dir = std::string(BEFT_SOURCE_DIR) + "/scenarios/sounds";
  bool json = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Benchmarks sound localisation: ear signals are rendered by convolving sources 2 m away with the KEMAR "
      "responses of the simulation, and localised against interaural templates of the MIT KEMAR (a different "
      "head). Per trial two blocks of 0.1 s: the head still, then turned by 20 degrees. Prints the median azimuth "
      "error after the turn, the share of front-back confusions without and with it, the share of two "
      "simultaneous sources (scenario sounds and noises, at least 30 degrees apart) found within 10 degrees, and "
      "the localiser's CPU time per block.",
      "beft-bench-hearing");
  app.add_option("--trials", o.single_trials, "one-source trials (azimuths spread evenly)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  app.add_option("--pairs", o.pair_trials, "two-source trials")->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--seed", o.seed, "random seed")->capture_default_str();
  app.add_option("--sounds", o.sounds_dir, "folder of the scenario sounds")->capture_default_str()->check(
      CLI::ExistingDirectory);
  app.add_flag("--json", o.json, "print one JSON object of the figures instead of text");
  return beft::parseCommandLine(app, argc, argv);
}

double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

struct Bench {
  KemarEars ears;
  BlockLocaliser localiser{InterauralTemplates::fromSofa()};
  std::vector<std::pair<std::string, std::vector<float>>> sounds;
  double localiser_seconds = 0;
  int blocks = 0;

  BlockLocalisation localise(const std::vector<float>& left, const std::vector<float>& right) {
    const double start = threadSeconds();
    BlockLocalisation found = localiser.localise(left, right);
    localiser_seconds += threadSeconds() - start;
    ++blocks;
    return found;
  }

  // The head still, then turned CCW by the resolving turn.
  std::pair<BlockLocalisation, AzimuthPosterior> hear(std::vector<PlacedSound> placed, uint64_t seed) {
    std::vector<float> left, right;
    ears.render(placed, left, right, kBlock, 1e-4f, seed);
    const BlockLocalisation before = localise(left, right);
    for (PlacedSound& s : placed) s.azimuth_deg -= kDefaultResolvingTurnDeg, s.offset += kBlock;
    ears.render(placed, left, right, kBlock, 1e-4f, seed + 1);
    BlockLocalisation after = localise(left, right);
    const AzimuthPosterior combined = combineAfterTurn(before.posterior, kDefaultResolvingTurnDeg, after.posterior);
    lastBefore = before;
    return {std::move(after), combined};
  }
  BlockLocalisation lastBefore;
};

long soundingOffset(const std::vector<float>& sound, std::mt19937_64& random) {
  std::uniform_int_distribution<long> offset(0, static_cast<long>(sound.size()) - 1);
  while (true) {
    const long o = offset(random);
    if (beft::bench::loopedRms(sound, o, kBlock) > 0.05 && beft::bench::loopedRms(sound, o + kBlock, kBlock) > 0.05)
      return o;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  try {
    Bench bench;
    std::mt19937_64 random(o.seed);
    bench.sounds.emplace_back("white", beft::bench::whiteNoise(44100, random));
    bench.sounds.emplace_back("pink", beft::bench::pinkNoise(44100, random));
    for (const char* name : {"talk", "help", "voice_radio", "siren", "engine", "fire"})
      bench.sounds.emplace_back(name, beft::bench::soundFile(o.sounds_dir + "/" + name + ".wav"));

    // One source: white, pink noise and two voices in turn, at azimuths spread evenly over the circle.
    std::vector<double> errors;
    int counted = 0, static_confusions = 0, turned_confusions = 0;
    for (int trial = 0; trial < o.single_trials; ++trial) {
      const auto& sound = bench.sounds[static_cast<std::size_t>(trial % 4)].second;
      const double truth = std::round(360.0 * trial / o.single_trials);
      const auto [after, combined] = bench.hear({{&sound, truth, soundingOffset(sound, random)}}, 1000 + trial);
      const double now = wrapDegrees(truth - kDefaultResolvingTurnDeg);
      const double first = bench.lastBefore.peaks.empty() ? 0 : bench.lastBefore.peaks[0].azimuth_deg;
      const double resolved = after.peaks.empty() ? 0 : resolveFrontBack(after.peaks[0].azimuth_deg, combined);
      errors.push_back(angularDistance(resolved, now));
      if (angularDistance(truth, frontBackMirror(truth)) > 20 && angularDistance(now, frontBackMirror(now)) > 20) {
        ++counted;
        static_confusions += angularDistance(first, frontBackMirror(truth)) < angularDistance(first, truth);
        turned_confusions += angularDistance(resolved, frontBackMirror(now)) < angularDistance(resolved, now);
      }
    }
    std::sort(errors.begin(), errors.end());

    // Two sources of different sounds, at least 30 degrees apart: found if one of the two strongest peaks,
    // put on the side the turn showed, is within 10 degrees.
    std::uniform_real_distribution<double> azimuth(0, 360);
    std::uniform_int_distribution<std::size_t> which(0, bench.sounds.size() - 1);
    int sources = 0, found = 0;
    for (int trial = 0; trial < o.pair_trials; ++trial) {
      std::size_t a = which(random), b = which(random);
      while (b == a) b = which(random);
      const double first = std::round(azimuth(random));
      double second = std::round(azimuth(random));
      while (angularDistance(first, second) < 30) second = std::round(azimuth(random));
      const auto& sa = bench.sounds[a].second;
      const auto& sb = bench.sounds[b].second;
      const auto [after, combined] = bench.hear(
          {{&sa, first, soundingOffset(sa, random)}, {&sb, second, soundingOffset(sb, random)}}, 50000 + trial);
      for (double truth : {first, second}) {
        ++sources;
        const double now = wrapDegrees(truth - kDefaultResolvingTurnDeg);
        bool hit = false;
        for (std::size_t p = 0; p < after.peaks.size() && p < 2; ++p)
          hit = hit || angularDistance(resolveFrontBack(after.peaks[p].azimuth_deg, combined), now) <= 10;
        found += hit;
      }
    }

    const double median = errors[errors.size() / 2];
    const double static_rate = counted > 0 ? static_cast<double>(static_confusions) / counted : 0;
    const double turned_rate = counted > 0 ? static_cast<double>(turned_confusions) / counted : 0;
    const double pairs = static_cast<double>(found) / sources;
    const double ms_per_block = 1e3 * bench.localiser_seconds / bench.blocks;
    if (o.json) {
      nlohmann::json figures = {{"median_azimuth_error_deg", median},
                                {"front_back_static", static_rate},
                                {"front_back_after_turn", turned_rate},
                                {"two_sources_within_10deg", pairs},
                                {"localise_ms_per_block", ms_per_block}};
      std::printf("%s\n", figures.dump().c_str());
    } else {
      std::printf("one source, %d trials (white, pink, two voices; 2 m; turn %.0f deg):\n", o.single_trials,
                  kDefaultResolvingTurnDeg);
      std::printf("  median azimuth error after the turn   %6.2f deg\n", median);
      std::printf("  front-back confusions, no turn        %6.3f  (of %d away from the interaural axis)\n",
                  static_rate, counted);
      std::printf("  front-back confusions, after the turn %6.3f\n", turned_rate);
      std::printf("two sources, %d trials: found within 10 deg %6.3f (of %d)\n", o.pair_trials, pairs, sources);
      std::printf("localiser: %.2f ms CPU per 0.1 s block (%d blocks)\n", ms_per_block, bench.blocks);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-bench-hearing: %s\n", e.what());
    return 1;
  }
  return 0;
}
