// The fusion expert class (without LCM): resumes the hypotheses of its run
// after a restart, not those of an earlier run; publishes the whole list at
// keyframes and the changes since at every tick.
#include <gtest/gtest.h>

#include <map>
#include <optional>

#include <beft/hypotheses_t.hpp>

#include "lib/common/channels.hpp"
#include "experts/fusion/fusion_expert.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "tests/experts/support/scene_builders.hpp"

using namespace beft;

namespace {

// What one firing published on each channel.
struct Collected : expert::Output {
  std::map<std::string, std::vector<uint8_t>> bytes;
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& encoded) override {
    EXPECT_EQ(bytes.count(channel), 0u) << "twice on " << channel;
    bytes[channel] = encoded;
  }
  template <typename Message>
  std::optional<Message> on(const std::string& channel) const {
    const auto it = bytes.find(channel);
    if (it == bytes.end()) return std::nullopt;
    Message message{};
    EXPECT_TRUE(expert::decodeMessage(channel, it->second.data(), static_cast<int>(it->second.size()), message));
    return message;
  }
};

template <typename Message>
bool feed(expert::Expert& e, const std::string& channel, const Message& m) {
  std::vector<uint8_t> bytes(m.getEncodedSize());
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return e.onMessage(channel, bytes.data(), static_cast<int>(bytes.size()));
}

hypotheses_t publishedAt(int64_t tick) {
  hypothesis_t h{};
  h.object_id = "victim";
  h.x = 21;
  h.y = 12;
  h.best_category = "person";
  h.confidence = 0.8;
  h.categories = {"person", "car"};
  h.fused = {0.8, 0.2};
  h.num_categories = 2;
  h.heard = true;
  h.heard_as = "person";
  h.seen_as = "";
  h.first_heard_utime = 0;
  h.first_seen_utime = -1;
  h.settled_utime = -1;
  hypotheses_t all{};
  all.tick = tick;
  all.utime = tick * 100000;
  all.hypotheses = {h};
  all.num_hypotheses = 1;
  return all;
}

// Fires fusion at a tick where nothing is perceived; returns what it published.
Collected fireQuietTickFor(fusion::FusionExpert& fusion, int64_t tick) {
  const auto s = test::scene({test::cylinderObject("victim", "person", 21, 12, 0.3, 1.8)}, tick);
  EXPECT_TRUE(feed(fusion, channels::kGroundTruth, s));
  expert::Firing firing;
  firing.expert = "fusion";
  firing.tick = tick;
  firing.utime = s.utime;
  firing.firing_id = tick + 1;
  Collected out;
  EXPECT_TRUE(fusion.fire(firing, out).ok);
  return out;
}

// The whole list of the tick, from the keyframe it published or was given.
hypotheses_t fireQuietTick(fusion::FusionExpert& fusion, int64_t tick, std::optional<hypotheses_t> keyframe = {}) {
  const Collected out = fireQuietTickFor(fusion, tick);
  if (auto published = out.on<hypotheses_t>(channels::kHypotheses)) keyframe = published;
  const auto changes = out.on<hypothesis_changes_t>(channels::kHypothesisChanges);
  hypotheses_t whole{};
  EXPECT_TRUE(changes && keyframe && wire::applyChanges(*keyframe, *changes, whole));
  return whole;
}

}  // namespace

TEST(FusionExpert, ResumesTheHypothesesOfItsRunAfterARestart) {
  fusion::FusionExpert fusion;
  fusion.startUp();
  ASSERT_TRUE(feed(fusion, channels::kHypotheses, publishedAt(499)));
  const hypotheses_t out = fireQuietTick(fusion, 500);
  ASSERT_EQ(out.num_hypotheses, 1);
  EXPECT_EQ(out.hypotheses[0].object_id, "victim");
  EXPECT_TRUE(out.hypotheses[0].heard);
  EXPECT_EQ(out.hypotheses[0].heard_as, "person");
  EXPECT_DOUBLE_EQ(out.hypotheses[0].x, 21);
}

TEST(FusionExpert, IgnoresHypothesesOfAnEarlierRunAndItsOwnEcho) {
  fusion::FusionExpert fusion;
  fusion.startUp();
  ASSERT_TRUE(feed(fusion, channels::kHypotheses, publishedAt(900)));  // an earlier, longer run
  const auto own_keyframe = fireQuietTickFor(fusion, 0).on<hypotheses_t>(channels::kHypotheses);
  ASSERT_TRUE(own_keyframe);
  EXPECT_EQ(own_keyframe->num_hypotheses, 0);
  ASSERT_TRUE(feed(fusion, channels::kHypotheses, publishedAt(0)));  // heard back while running
  EXPECT_EQ(fireQuietTick(fusion, 1, own_keyframe).num_hypotheses, 0);
}

TEST(FusionExpert, TheWholeListAtKeyframesAndTheChangesSinceAtEveryTick) {
  fusion::FusionExpert fusion;
  fusion.startUp();
  for (int64_t tick : {0, 1, 99, 100, 101}) {
    const Collected out = fireQuietTickFor(fusion, tick);
    const auto keyframe = out.on<hypotheses_t>(channels::kHypotheses);
    const auto changes = out.on<hypothesis_changes_t>(channels::kHypothesisChanges);
    ASSERT_TRUE(changes) << tick;
    EXPECT_EQ(changes->tick, tick);
    EXPECT_EQ(changes->keyframe_tick, tick < 100 ? 0 : 100);
    EXPECT_EQ(keyframe.has_value(), tick % 100 == 0) << tick;
  }
}

TEST(FusionExpert, ResumesFromTheLastKeyframeWithTheChangesSince) {
  fusion::FusionExpert fusion;
  fusion.startUp();
  const hypotheses_t keyframe = publishedAt(400);
  hypotheses_t at_499 = publishedAt(499);
  hypothesis_t radio = at_499.hypotheses[0];
  radio.object_id = "radio";
  radio.x = 3;
  at_499.hypotheses.push_back(radio);
  at_499.num_hypotheses = 2;
  ASSERT_TRUE(feed(fusion, channels::kHypotheses, keyframe));
  ASSERT_TRUE(feed(fusion, channels::kHypothesisChanges, wire::changesSince(keyframe, at_499)));
  const hypotheses_t out = fireQuietTick(fusion, 501, keyframe);  // a list of changes since tick 400
  ASSERT_EQ(out.num_hypotheses, 2);
  EXPECT_EQ(out.hypotheses[1].object_id, "radio");
  EXPECT_DOUBLE_EQ(out.hypotheses[1].x, 3);
}

TEST(FusionExpert, ChangesOfAnotherKeyframeAreNotAppliedToTheResumedOne) {
  fusion::FusionExpert fusion;
  fusion.startUp();
  const hypotheses_t keyframe = publishedAt(400);
  hypotheses_t other_keyframe = publishedAt(300);
  other_keyframe.hypotheses.clear();
  other_keyframe.num_hypotheses = 0;
  ASSERT_TRUE(feed(fusion, channels::kHypotheses, keyframe));
  ASSERT_TRUE(feed(fusion, channels::kHypothesisChanges, wire::changesSince(other_keyframe, publishedAt(499))));
  const hypotheses_t out = fireQuietTick(fusion, 500);
  ASSERT_EQ(out.num_hypotheses, 1);  // the keyframe's
  EXPECT_EQ(out.hypotheses[0].object_id, "victim");
}
