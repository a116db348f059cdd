// A keyframe and the changes since it make the whole list of hypotheses.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "lib/wire/hypothesis_changes.hpp"

using namespace beft;

namespace {
hypothesis_t hypothesis(const std::string& id, double x, double confidence) {
  hypothesis_t h{};
  h.object_id = id;
  h.x = x;
  h.best_category = "person";
  h.confidence = confidence;
  h.categories = {"person", "radio"};
  h.fused = {confidence, 1 - confidence};
  h.num_categories = 2;
  h.first_heard_utime = h.first_seen_utime = h.settled_utime = -1;
  return h;
}
hypotheses_t list(int64_t tick, std::vector<hypothesis_t> hypotheses) {
  hypotheses_t all{};
  all.utime = tick * 100000;
  all.tick = tick;
  all.hypotheses = std::move(hypotheses);
  all.num_hypotheses = static_cast<int32_t>(all.hypotheses.size());
  return all;
}
std::vector<uint8_t> encoded(const hypotheses_t& m) {
  std::vector<uint8_t> bytes(m.getEncodedSize());
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}
}  // namespace

TEST(HypothesisChanges, CarryOnlyWhatChangedOrIsNewAndGiveTheWholeListBack) {
  const hypotheses_t keyframe = list(0, {hypothesis("a", 1, 0.5), hypothesis("b", 2, 0.5), hypothesis("c", 3, 0.5)});
  hypotheses_t later = list(7, {hypothesis("a", 1, 0.5), hypothesis("b", 2, 0.9), hypothesis("c", 3, 0.5),
                                hypothesis("d", 4, 0.6)});
  later.hypotheses[2].verified = true;
  const hypothesis_changes_t changes = wire::changesSince(keyframe, later);
  EXPECT_EQ(changes.tick, 7);
  EXPECT_EQ(changes.utime, 700000);
  EXPECT_EQ(changes.keyframe_tick, 0);
  EXPECT_EQ(changes.num_hypotheses, 4);
  ASSERT_EQ(changes.num_changed, 3);
  EXPECT_EQ(changes.changed[0].object_id, "b");
  EXPECT_EQ(changes.changed[1].object_id, "c");
  EXPECT_EQ(changes.changed[2].object_id, "d");

  hypotheses_t whole{};
  ASSERT_TRUE(wire::applyChanges(keyframe, changes, whole));
  EXPECT_EQ(encoded(whole), encoded(later));
}

// Lists in another order than the keyframe's (the usual one is the same
// order, compared pairwise): the same hypotheses found changed, in the
// later list's order.
TEST(HypothesisChanges, AnotherOrderThanTheKeyframesFindsTheSameChanges) {
  const hypotheses_t keyframe = list(0, {hypothesis("a", 1, 0.5), hypothesis("b", 2, 0.5), hypothesis("c", 3, 0.5)});
  const hypotheses_t reordered = list(7, {hypothesis("c", 3, 0.5), hypothesis("d", 4, 0.6), hypothesis("a", 1, 0.8),
                                          hypothesis("b", 2, 0.5)});
  const hypothesis_changes_t changes = wire::changesSince(keyframe, reordered);
  ASSERT_EQ(changes.num_changed, 2);
  EXPECT_EQ(changes.changed[0].object_id, "d");
  EXPECT_EQ(changes.changed[1].object_id, "a");
  // Fewer than the keyframe holds: only what differs.
  const hypotheses_t fewer = list(8, {hypothesis("a", 1, 0.5), hypothesis("b", 2, 0.7)});
  const hypothesis_changes_t shrunk = wire::changesSince(keyframe, fewer);
  ASSERT_EQ(shrunk.num_changed, 1);
  EXPECT_EQ(shrunk.changed[0].object_id, "b");
  EXPECT_EQ(shrunk.num_hypotheses, 2);
}

TEST(HypothesisChanges, RefuseAnotherKeyframeOrACountThatDoesNotAddUp) {
  const hypotheses_t keyframe = list(10, {hypothesis("a", 1, 0.5)});
  hypothesis_changes_t changes = wire::changesSince(keyframe, list(12, {hypothesis("a", 1, 0.5), hypothesis("b", 1, 0.5)}));
  hypotheses_t whole = list(99, {});
  hypotheses_t other_keyframe = keyframe;
  other_keyframe.tick = 0;
  EXPECT_FALSE(wire::applyChanges(other_keyframe, changes, whole));
  changes.num_hypotheses = 3;  // one went missing
  EXPECT_FALSE(wire::applyChanges(keyframe, changes, whole));
  EXPECT_EQ(whole.tick, 99);  // untouched
}

// Random lists that grow and change as fusion's do: every tick's list comes
// back byte for byte from the keyframe and that tick's changes alone.
TEST(HypothesisChanges, EveryTickOfARandomRunComesBackExactly) {
  std::mt19937 random(5);
  std::vector<hypothesis_t> current;
  hypotheses_t keyframe{};
  for (int64_t tick = 0; tick < 300; ++tick) {
    if (random() % 4 == 0) current.push_back(hypothesis("o" + std::to_string(current.size()), tick, 0.5));
    for (auto& h : current)
      if (random() % 10 == 0) h.confidence = (random() % 100) / 100.0;
    const hypotheses_t whole = list(tick, current);
    if (tick % 50 == 0) keyframe = whole;
    const hypothesis_changes_t changes = wire::changesSince(keyframe, whole);
    EXPECT_LE(changes.num_changed, changes.num_hypotheses);
    hypotheses_t back{};
    ASSERT_TRUE(wire::applyChanges(keyframe, changes, back)) << tick;
    ASSERT_EQ(encoded(back), encoded(whole)) << tick;
  }
}

// A change in any one field of a hypothesis is a change: a field the
// comparison missed would leave receivers with a stale hypothesis.
TEST(HypothesisChanges, AChangeInAnyOneFieldIsListed) {
  const std::vector<std::pair<const char*, std::function<void(hypothesis_t&)>>> changes_of_one_field = {
      {"x", [](hypothesis_t& h) { h.x += 1; }},
      {"y", [](hypothesis_t& h) { h.y += 1; }},
      {"z", [](hypothesis_t& h) { h.z += 1; }},
      {"located", [](hypothesis_t& h) { h.located = !h.located; }},
      {"best_category", [](hypothesis_t& h) { h.best_category = "radio"; }},
      {"confidence", [](hypothesis_t& h) { h.confidence += 0.1; }},
      {"categories", [](hypothesis_t& h) { h.categories[1] = "siren"; }},
      {"fused", [](hypothesis_t& h) { h.fused[1] += 0.1; }},
      {"seen", [](hypothesis_t& h) { h.seen = !h.seen; }},
      {"heard", [](hypothesis_t& h) { h.heard = !h.heard; }},
      {"seen_as", [](hypothesis_t& h) { h.seen_as = "person"; }},
      {"heard_as", [](hypothesis_t& h) { h.heard_as = "person"; }},
      {"verified", [](hypothesis_t& h) { h.verified = !h.verified; }},
      {"falsified", [](hypothesis_t& h) { h.falsified = !h.falsified; }},
      {"first_heard_utime", [](hypothesis_t& h) { h.first_heard_utime = 5; }},
      {"first_seen_utime", [](hypothesis_t& h) { h.first_seen_utime = 5; }},
      {"settled_utime", [](hypothesis_t& h) { h.settled_utime = 5; }},
  };
  const hypotheses_t keyframe = list(0, {hypothesis("a", 1, 0.5)});
  for (const auto& [field, change] : changes_of_one_field) {
    hypotheses_t later = list(3, {hypothesis("a", 1, 0.5)});
    change(later.hypotheses[0]);
    const hypothesis_changes_t changes = wire::changesSince(keyframe, later);
    EXPECT_EQ(changes.num_changed, 1) << "a change of " << field << " was not listed";
  }
}
