// The localiser in a reverberant room (trials/room_trials): two and three
// talkers over the full circle in the 16 x 12 x 4 m shoebox of T60 0.6 s,
// heard before and after one head turn, for one block of 0.1 s at each pose
// and for 0.8 s, as ./beft bench hearing listens. Fixed seeds: deterministic. ./beft bench
// hearing runs more trials of the same, in more rooms.
#include <gtest/gtest.h>

#include <cstdio>

#include "lib/hearing/trials/room_trials.hpp"

namespace beft::hearing {
namespace {

// The room of T60 0.6 s (reflections to order 2 and the tail) and the
// reverberant profile's trials in it.
class RoomLocalisation : public ::testing::Test {
 protected:
  const BinauralRenderer renderer{HrirSet::loadKemar(), trials::kRate};
  const trials::TrialRoom room = trials::trialRoom(0.6, renderer.hrirs(), 2);
  trials::RoomTrials reverberant{renderer,
                                 BlockLocaliser(InterauralTemplates::fromSofa(), LocaliserConfig::reverberant())};
};

TEST_F(RoomLocalisation, TheReverberantProfileFindsTwoTalkersInARoom) {
  trials::RoomTrials plain(renderer, BlockLocaliser(InterauralTemplates::fromSofa()));
  const trials::RoomFigures before = plain.run(room, 2, 40, 7, 1, 1);
  const trials::RoomFigures after = reverberant.run(room, 2, 40, 7, 1, 1);
  std::printf("T60 0.6 s, two talkers: within 5 deg %.3f (defaults), %.3f (reverberant); front-back after the "
              "turn %.3f, %.3f\n",
              before.within_5deg, after.within_5deg, before.front_back_after_turn, after.front_back_after_turn);
  EXPECT_GE(after.within_5deg, 0.8);
  EXPECT_GT(after.within_5deg, before.within_5deg);
  EXPECT_LE(after.front_back_after_turn, 0.06);
  EXPECT_LE(after.median_error_deg, 3.0);
}

TEST_F(RoomLocalisation, ListeningASentenceAtEachPoseFindsTheThirdTalker) {
  const trials::RoomFigures one_block = reverberant.run(room, 3, 30, 11, 1, 1);
  const trials::RoomFigures sentence = reverberant.run(room, 3, 30, 11, 1, trials::kSentenceBlocksPerPose);
  std::printf("T60 0.6 s, three talkers: within 5 deg %.3f (0.1 s at each pose), %.3f (0.8 s); front-back after "
              "the turn %.3f, %.3f\n",
              one_block.within_5deg, sentence.within_5deg, one_block.front_back_after_turn,
              sentence.front_back_after_turn);
  EXPECT_EQ(sentence.blocks_per_pose, trials::kSentenceBlocksPerPose);
  EXPECT_GE(sentence.within_5deg, 0.85);
  EXPECT_GE(sentence.within_5deg, one_block.within_5deg + 0.1);
  EXPECT_LE(sentence.front_back_after_turn, 0.04);
}

}  // namespace
}  // namespace beft::hearing
