// The fusion expert class (without LCM): resumes the hypotheses of its run
// after a restart, not those of an earlier run.
#include <gtest/gtest.h>

#include <beft/hypotheses_t.hpp>

#include "channels.hpp"
#include "fusion_expert.hpp"
#include "scene_builders.hpp"

using namespace beft;

namespace {

struct Collected : expert::Output {
  std::vector<uint8_t> hypotheses;
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    if (channel == channels::kHypotheses) hypotheses = bytes;
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
hypotheses_t fireQuietTick(fusion::FusionExpert& fusion, int64_t tick) {
  const auto s = test::scene({test::cylinderObject("victim", "person", 21, 12, 0.3, 1.8)}, tick);
  EXPECT_TRUE(feed(fusion, channels::kGroundTruth, s));
  expert::Firing firing;
  firing.expert = "fusion";
  firing.tick = tick;
  firing.utime = s.utime;
  firing.firing_id = tick + 1;
  Collected out;
  EXPECT_TRUE(fusion.fire(firing, out).ok);
  hypotheses_t published{};
  EXPECT_TRUE(expert::decodeMessage("HYPOTHESES", out.hypotheses.data(), static_cast<int>(out.hypotheses.size()), published));
  return published;
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
  EXPECT_EQ(fireQuietTick(fusion, 0).num_hypotheses, 0);
  ASSERT_TRUE(feed(fusion, channels::kHypotheses, publishedAt(0)));  // heard back while running
  EXPECT_EQ(fireQuietTick(fusion, 1).num_hypotheses, 0);
}
