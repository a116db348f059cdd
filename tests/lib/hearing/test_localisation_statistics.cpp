// The localiser on ear signals through the KEMAR responses the simulation
// renders with, against templates from the MIT KEMAR: a head turn of
// kDefaultResolvingTurnDeg after each first block, both blocks then pooled
// (trials/localisation_trials).
// Fixed seeds: deterministic. ./beft bench hearing runs more trials of the same.
#include <gtest/gtest.h>

#include <cstdio>

#include "lib/hearing/trials/localisation_trials.hpp"

namespace beft::hearing {
namespace {

trials::LocalisationTrials& localisationTrials() {
  static trials::LocalisationTrials instance{BlockLocaliser(InterauralTemplates::fromSofa())};
  return instance;
}

TEST(LocalisationStatistics, OneBroadbandSourceAnywhereOnTheCircle) {
  const trials::OneSourceFigures figures = localisationTrials().oneSource(72, 101);
  std::printf("median error: %.2f deg (front-back folded, one block), %.2f deg (after the turn); front-back "
              "confusions %.3f without turning, %.3f after it (of %d)\n",
              figures.median_error_folded_deg, figures.median_error_after_turn_deg, figures.front_back_static,
              figures.front_back_after_turn, figures.counted);
  EXPECT_EQ(figures.unheard, 0);
  EXPECT_GT(figures.counted, 50);
  EXPECT_LE(figures.median_error_folded_deg, 3.0);
  EXPECT_LE(figures.median_error_after_turn_deg, 3.0);
  EXPECT_LT(figures.front_back_after_turn, 0.05);
  EXPECT_LT(figures.front_back_after_turn, 0.5 * figures.front_back_static);
}

TEST(LocalisationStatistics, TwoSimultaneousSourcesWithDifferentSpectra) {
  const trials::TwoSourceFigures figures = localisationTrials().twoSources(40, 202);
  std::printf("two sources: %.3f found within 10 deg after the turn, %.3f within 10 deg front-back folded "
              "(strongest two peaks, %d sources)\n",
              figures.found_after_turn, figures.found_folded, figures.sources);
  EXPECT_EQ(figures.sources, 80);
  EXPECT_GE(figures.found_after_turn, 0.85);
}

}  // namespace
}  // namespace beft::hearing
