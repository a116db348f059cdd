#include "lib/hearing/trials/localisation_trials.hpp"

#include <time.h>

#include <algorithm>
#include <random>

namespace beft::hearing::trials {

namespace {

double threadSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// An offset where the sound is heard through both blocks (no pause of speech).
long soundingOffset(const std::vector<float>& sound, std::mt19937_64& random) {
  std::uniform_int_distribution<long> offset(0, static_cast<long>(sound.size()) - 1);
  while (true) {
    const long o = offset(random);
    if (loopedRms(sound, o, kBlock) > 0.05 && loopedRms(sound, o + kBlock, kBlock) > 0.05) return o;
  }
}

}  // namespace

LocalisationTrials::LocalisationTrials(BlockLocaliser localiser, const std::string& sounds_dir)
    : localiser_(std::move(localiser)) {
  std::mt19937_64 random(17);
  sounds_.emplace_back("white", whiteNoise(44100, random));
  sounds_.emplace_back("pink", pinkNoise(44100, random));
  for (const char* name : {"talk", "help", "voice_radio", "siren", "engine", "fire"})
    sounds_.emplace_back(name, scenarioSound(name, 0.1f, sounds_dir));
}

BlockLocalisation LocalisationTrials::localise(const std::vector<EarBlock>& blocks) {
  const double start = threadSeconds();
  BlockLocalisation found = localiser_.localise(blocks);
  localise_seconds_ += threadSeconds() - start;
  blocks_ += static_cast<int64_t>(blocks.size());
  return found;
}

// Two blocks: the head still, then turned by the resolving turn (each source then kDefaultResolvingTurnDeg further
// right); the first alone, and both pooled in the frame of the turned head.
LocalisationTrials::Heard LocalisationTrials::hear(std::vector<PlacedSound> sounds, uint64_t seed) {
  const double turn = kDefaultResolvingTurnDeg;
  Heard heard;
  std::vector<float> left_before, right_before, left_after, right_after;
  ears_.render(sounds, left_before, right_before, kBlock, 1e-4f, seed);
  heard.before = localise({EarBlock{left_before, right_before, 0.0}});
  for (PlacedSound& s : sounds) s.azimuth_deg -= turn, s.offset += kBlock;
  ears_.render(sounds, left_after, right_after, kBlock, 1e-4f, seed + 1);
  heard.after_turn = localise({EarBlock{left_before, right_before, turn}, EarBlock{left_after, right_after, 0.0}});
  return heard;
}

OneSourceFigures LocalisationTrials::oneSource(int trials, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> azimuth(0, 360);
  std::vector<double> folded_errors, turned_errors;
  OneSourceFigures figures;
  figures.trials = trials;
  int static_confusions = 0, turned_confusions = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const auto& sound = sounds_[static_cast<std::size_t>(trial % 4)].second;
    const double truth = std::round(azimuth(random));
    const Heard heard = hear({{&sound, truth, soundingOffset(sound, random)}}, 1000 + static_cast<uint64_t>(trial));
    if (heard.before.peaks.empty() || heard.after_turn.peaks.empty()) {
      ++figures.unheard;  // counted as the worst error below, never as a confusion
      folded_errors.push_back(90);
      turned_errors.push_back(180);
      continue;
    }
    const double first = heard.before.peaks[0].azimuth_deg;
    folded_errors.push_back(std::min(angularDistance(first, truth), angularDistance(first, frontBackMirror(truth))));
    const double now = wrapDegrees(truth - kDefaultResolvingTurnDeg);
    const double resolved = heard.after_turn.peaks[0].azimuth_deg;
    turned_errors.push_back(angularDistance(resolved, now));
    // Front-back confusions count where the mirror image is a different direction.
    if (angularDistance(truth, frontBackMirror(truth)) > 20 && angularDistance(now, frontBackMirror(now)) > 20) {
      ++figures.counted;
      static_confusions += angularDistance(first, frontBackMirror(truth)) < angularDistance(first, truth);
      turned_confusions += angularDistance(resolved, frontBackMirror(now)) < angularDistance(resolved, now);
    }
  }
  figures.median_error_folded_deg = median(folded_errors);
  figures.median_error_after_turn_deg = median(turned_errors);
  if (figures.counted > 0) {
    figures.front_back_static = static_cast<double>(static_confusions) / figures.counted;
    figures.front_back_after_turn = static_cast<double>(turned_confusions) / figures.counted;
  }
  return figures;
}

TwoSourceFigures LocalisationTrials::twoSources(int trials, uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> azimuth(0, 360);
  std::uniform_int_distribution<std::size_t> which(0, sounds_.size() - 1);
  int found_after_turn = 0, found_folded = 0;
  TwoSourceFigures figures;
  for (int trial = 0; trial < trials; ++trial) {
    std::size_t a = which(random), b = which(random);
    while (b == a) b = which(random);
    const double first = std::round(azimuth(random));
    double second = std::round(azimuth(random));
    while (angularDistance(first, second) < 30) second = std::round(azimuth(random));
    const auto& sa = sounds_[a].second;
    const auto& sb = sounds_[b].second;
    const Heard heard = hear({{&sa, first, soundingOffset(sa, random)}, {&sb, second, soundingOffset(sb, random)}},
                             5000 + static_cast<uint64_t>(trial));
    for (double truth : {first, second}) {
      ++figures.sources;
      const double now = wrapDegrees(truth - kDefaultResolvingTurnDeg);
      bool found = false, folded = false;
      for (std::size_t p = 0; p < heard.after_turn.peaks.size() && p < 2; ++p) {
        const double peak = heard.after_turn.peaks[p].azimuth_deg;
        found = found || angularDistance(peak, now) <= 10;
        folded = folded || std::min(angularDistance(peak, now), angularDistance(peak, frontBackMirror(now))) <= 10;
      }
      found_after_turn += found;
      found_folded += folded;
    }
  }
  if (figures.sources > 0) {
    figures.found_after_turn = static_cast<double>(found_after_turn) / figures.sources;
    figures.found_folded = static_cast<double>(found_folded) / figures.sources;
  }
  return figures;
}

}  // namespace beft::hearing::trials
