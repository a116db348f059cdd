// Tick-indexed input ports: find the message of a firing's tick, not just
// the newest one.
#include <gtest/gtest.h>

#include <beft/geometry_percepts_t.hpp>
#include <beft/robot_state_t.hpp>

#include <algorithm>

#include "tests/experts/support/scene_builders.hpp"
#include "lib/expert/expert.hpp"
#include "lib/expert/hypotheses_input.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "lib/expert/obstacle_map_input.hpp"
#include "lib/expert/scene_input.hpp"

using namespace beft;

namespace {
// An expert with nothing but the port under test.
struct PortOwner : expert::Expert {
  std::string name() const override { return "owner"; }
  std::string description() const override { return "test"; }
  expert::Outcome fire(const expert::Firing&, expert::Output&) override { return expert::Outcome::success(); }
};

expert::Firing firingAt(int64_t tick) {
  expert::Firing firing;
  firing.tick = tick;
  return firing;
}
}  // namespace

TEST(TickInput, FindsEachStoredTickAndNothingElse) {
  PortOwner owner;
  expert::TickInput<robot_state_t> channel(owner, channels::kRobotState, 4);
  EXPECT_EQ(channel.ofTick(0), nullptr);
  for (int k = 0; k < 6; ++k) channel.store(test::robot(k, 0, 0, 0, 0, k));
  for (int k = 2; k < 6; ++k) {
    ASSERT_NE(channel.ofTick(k), nullptr) << k;
    EXPECT_DOUBLE_EQ(channel.ofTick(k)->x, k);
  }
  EXPECT_EQ(channel.ofTick(1), nullptr);  // dropped: capacity 4
  EXPECT_EQ(channel.ofTick(6), nullptr);  // not yet arrived
  EXPECT_DOUBLE_EQ(channel.latest()->x, 5);
}

TEST(TickInput, DecodesBytesAndRefusesGarbage) {
  PortOwner owner;
  expert::TickInput<robot_state_t> channel(owner, channels::kRobotState);
  const robot_state_t state = test::robot(3, 4, 5, 0, 0, 9);
  std::vector<uint8_t> bytes(state.getEncodedSize());
  state.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  EXPECT_TRUE(channel.receive(bytes.data(), static_cast<int>(bytes.size())));
  ASSERT_TRUE(channel.has(9));
  EXPECT_DOUBLE_EQ(channel.ofTick(9)->y, 4);
  const uint8_t garbage[5] = {1, 2, 3, 4, 5};
  EXPECT_FALSE(channel.receive(garbage, 5));
  EXPECT_EQ(channel.latest()->tick, 9);
}

// Messages are decoded over the one the history dropped last: a shorter
// list after a longer one, other strings, or garbage in between leave
// nothing of the message before in what is stored.
TEST(TickInput, EachStoredMessageIsExactlyTheOneSent) {
  PortOwner owner;
  expert::TickInput<geometry_percepts_t> channel(owner, channels::kGeometry, 2);
  std::vector<geometry_percepts_t> sent;
  const int lengths[] = {5, 2, 7, 0, 3, 9, 1, 4};
  for (int tick = 0; tick < 8; ++tick) {
    geometry_percepts_t message{};
    message.utime = tick * 100000;
    message.tick = tick;
    for (int i = 0; i < lengths[tick]; ++i) {
      geometry_percept_t p{};
      p.object_id = std::string(static_cast<size_t>(1 + (tick * 7 + i) % 13), static_cast<char>('a' + tick));
      p.distance = tick + 0.1 * i;
      p.acoustic = (tick + i) % 2 == 1;
      message.percepts.push_back(p);
    }
    message.num_percepts = lengths[tick];
    std::vector<uint8_t> bytes(message.getEncodedSize());
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    ASSERT_TRUE(channel.receive(bytes.data(), static_cast<int>(bytes.size())));
    bytes.resize(bytes.size() / 2);  // cut: refused, and nothing stored changes
    EXPECT_FALSE(channel.receive(bytes.data(), static_cast<int>(bytes.size())));
    sent.push_back(message);
    for (int k = std::max(0, tick - 1); k <= tick; ++k) {
      const geometry_percepts_t* stored = channel.ofTick(k);
      ASSERT_NE(stored, nullptr) << "tick " << k;
      std::vector<uint8_t> expected(sent[k].getEncodedSize()), got(stored->getEncodedSize());
      sent[k].encode(expected.data(), 0, static_cast<int>(expected.size()));
      stored->encode(got.data(), 0, static_cast<int>(got.size()));
      EXPECT_EQ(got, expected) << "tick " << k << " after receiving tick " << tick;
    }
  }
}

TEST(TickInput, ARepeatedTickGivesTheNewestCopy) {
  PortOwner owner;
  expert::TickInput<robot_state_t> channel(owner, channels::kRobotState);
  channel.store(test::robot(1, 0, 0, 0, 0, 2));
  channel.store(test::robot(2, 0, 0, 0, 0, 2));
  channel.store(test::robot(3, 0, 0, 0, 0, 3));
  ASSERT_NE(channel.ofTick(2), nullptr);
  EXPECT_DOUBLE_EQ(channel.ofTick(2)->x, 2);
}

namespace {
template <typename Message>
bool deliver(expert::Expert& owner, const char* channel, const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return owner.onMessage(channel, bytes.data(), static_cast<int>(bytes.size()));
}
scene_version_t version(int64_t tick, int64_t scene_tick) {
  scene_version_t v{};
  v.utime = tick * 100000;
  v.tick = tick;
  v.scene_tick = scene_tick;
  return v;
}
}  // namespace

TEST(SceneInput, TheGroundTruthInForceIsRestampedForEachTick) {
  PortOwner owner;
  expert::SceneInput scene(owner);
  deliver(owner, channels::kGroundTruth.name, test::scene({test::pointObject("victim", "person", 1, 2)}, 0));
  for (int64_t k = 0; k <= 3; ++k) ASSERT_TRUE(deliver(owner, channels::kSceneVersion.name, version(k, 0)));
  for (int64_t k = 0; k <= 3; ++k) {
    const scene_objects_t* truth = scene.ofTick(k);
    ASSERT_NE(truth, nullptr) << k;
    EXPECT_EQ(truth->tick, k);
    EXPECT_EQ(truth->utime, k * 100000);
    ASSERT_EQ(truth->num_objects, 1);
    EXPECT_EQ(truth->objects[0].id, "victim");
    EXPECT_FALSE(scene.lacksTick(k));
  }
  // Tick 4's version has not arrived: the blackboard is asked for GT_VERSION.
  EXPECT_EQ(scene.ofTick(4), nullptr);
  EXPECT_TRUE(scene.lacksTick(4));
  EXPECT_EQ(scene.lackingChannel(4), channels::kSceneVersion.name);
  // It says the scene changed at tick 4, whose GT_OBJECTS is still on its way: ask for that.
  deliver(owner, channels::kSceneVersion.name, version(4, 4));
  EXPECT_EQ(scene.ofTick(4), nullptr);
  EXPECT_EQ(scene.lackingChannel(4), channels::kGroundTruth.name);
  deliver(owner, channels::kGroundTruth.name, test::scene({test::pointObject("victim", "person", 5, 2)}, 4));
  ASSERT_NE(scene.ofTick(4), nullptr);
  EXPECT_DOUBLE_EQ(scene.ofTick(4)->objects[0].x, 5);
  EXPECT_DOUBLE_EQ(scene.ofTick(3)->objects[0].x, 1);  // earlier ticks keep theirs
}

TEST(SceneInput, LogsFromBeforeVersionsGiveEachTicksOwnMessage) {
  PortOwner owner;
  expert::SceneInput scene(owner);
  for (int64_t k = 0; k < 3; ++k)
    deliver(owner, channels::kGroundTruth.name, test::scene({test::pointObject("p", "person", k, 0)}, k));
  for (int64_t k = 0; k < 3; ++k) {
    ASSERT_NE(scene.ofTick(k), nullptr) << k;
    EXPECT_DOUBLE_EQ(scene.ofTick(k)->objects[0].x, k);
  }
  EXPECT_EQ(scene.ofTick(3), nullptr);
  const uint8_t garbage[3] = {1, 2, 3};
  EXPECT_FALSE(scene.receive(garbage, 3));
  EXPECT_EQ(scene.latest()->tick, 2);
}

namespace {
hypotheses_t hypothesesOf(int64_t tick, const std::vector<std::pair<std::string, double>>& positions) {
  hypotheses_t all{};
  all.utime = tick * 100000;
  all.tick = tick;
  for (const auto& [id, x] : positions) {
    hypothesis_t h{};
    h.object_id = id;
    h.x = x;
    all.hypotheses.push_back(h);
  }
  all.num_hypotheses = static_cast<int32_t>(all.hypotheses.size());
  return all;
}
}  // namespace

TEST(HypothesesInput, AKeyframeAndEachTicksChangesGiveThatTicksWholeList) {
  PortOwner owner;
  expert::HypothesesInput hypotheses(owner);
  EXPECT_TRUE(hypotheses.empty());
  const hypotheses_t keyframe = hypothesesOf(0, {{"a", 1}});
  ASSERT_TRUE(deliver(owner, channels::kHypotheses.name, keyframe));
  ASSERT_TRUE(deliver(owner, channels::kHypothesisChanges.name, wire::changesSince(keyframe, keyframe)));
  ASSERT_TRUE(deliver(owner, channels::kHypothesisChanges.name,
                      wire::changesSince(keyframe, hypothesesOf(1, {{"a", 2}}))));
  ASSERT_TRUE(deliver(owner, channels::kHypothesisChanges.name,
                      wire::changesSince(keyframe, hypothesesOf(2, {{"a", 2}, {"b", 5}}))));
  ASSERT_NE(hypotheses.ofTick(0), nullptr);
  EXPECT_DOUBLE_EQ(hypotheses.ofTick(0)->hypotheses[0].x, 1);
  const hypotheses_t* second = hypotheses.ofTick(2);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(second->tick, 2);
  EXPECT_EQ(second->utime, 200000);
  ASSERT_EQ(second->num_hypotheses, 2);
  EXPECT_DOUBLE_EQ(second->hypotheses[0].x, 2);
  EXPECT_EQ(second->hypotheses[1].object_id, "b");
  EXPECT_EQ(hypotheses.ofTick(1)->num_hypotheses, 1);
  EXPECT_EQ(hypotheses.latest()->tick, 2);

  // Tick 3's changes are missing: ask for them; they name keyframe 3, which is
  // still on its way: ask for HYPOTHESES.
  EXPECT_TRUE(hypotheses.lacksTick(3));
  EXPECT_EQ(hypotheses.lackingChannel(3), channels::kHypothesisChanges.name);
  const hypotheses_t keyframe3 = hypothesesOf(3, {{"a", 7}, {"b", 5}});
  deliver(owner, channels::kHypothesisChanges.name, wire::changesSince(keyframe3, keyframe3));
  EXPECT_EQ(hypotheses.ofTick(3), nullptr);
  EXPECT_EQ(hypotheses.lackingChannel(3), channels::kHypotheses.name);
  EXPECT_EQ(hypotheses.latest()->tick, 0);  // the newest list it can make: the keyframe before
  deliver(owner, channels::kHypotheses.name, keyframe3);
  ASSERT_NE(hypotheses.ofTick(3), nullptr);
  EXPECT_DOUBLE_EQ(hypotheses.ofTick(3)->hypotheses[0].x, 7);
  EXPECT_DOUBLE_EQ(hypotheses.ofTick(1)->hypotheses[0].x, 2);  // earlier ticks keep theirs
  EXPECT_FALSE(hypotheses.lacksTick(3));
}

TEST(HypothesesInput, LogsFromBeforeChangesGiveEachTicksOwnList) {
  PortOwner owner;
  expert::HypothesesInput hypotheses(owner);
  for (int64_t k = 0; k < 3; ++k) deliver(owner, channels::kHypotheses.name, hypothesesOf(k, {{"a", double(k)}}));
  for (int64_t k = 0; k < 3; ++k) {
    ASSERT_NE(hypotheses.ofTick(k), nullptr) << k;
    EXPECT_DOUBLE_EQ(hypotheses.ofTick(k)->hypotheses[0].x, k);
  }
  EXPECT_TRUE(hypotheses.lacksTick(3));
  EXPECT_EQ(hypotheses.lackingChannel(3), channels::kHypotheses.name);
  const uint8_t garbage[3] = {1, 2, 3};
  EXPECT_FALSE(hypotheses.receive(garbage, 3));
  EXPECT_EQ(hypotheses.latest()->tick, 2);
}

// An expert that fires before the fusion in each tick reads the list of the
// tick before: a firing of tick k lacks only tick k - 1's, and asks for it.
TEST(HypothesesInput, ReadingTheTickBeforeAFiringLacksOnlyThatTicksList) {
  PortOwner owner;
  expert::HypothesesInput hypotheses(owner);
  hypotheses.readTheTickBefore();
  const hypotheses_t keyframe = hypothesesOf(0, {{"a", 1}});
  deliver(owner, channels::kHypotheses.name, keyframe);
  deliver(owner, channels::kHypothesisChanges.name, wire::changesSince(keyframe, keyframe));
  deliver(owner, channels::kHypothesisChanges.name, wire::changesSince(keyframe, hypothesesOf(1, {{"a", 2}})));
  EXPECT_FALSE(hypotheses.lacksTick(1));
  EXPECT_FALSE(hypotheses.lacksTick(2));  // tick 2's own list comes after its firing
  EXPECT_TRUE(hypotheses.lacksTick(3));
  EXPECT_EQ(hypotheses.lackingChannel(3), channels::kHypothesisChanges.name);
  // Every port of the owner agrees (the changes' own port included).
  EXPECT_TRUE(owner.inputsLacking(firingAt(2)).empty());
  EXPECT_FALSE(owner.inputsLacking(firingAt(3)).empty());
}

TEST(ObstacleMapInput, TheKeyframeWithEachTicksChangesIsThatTicksMap) {
  PortOwner owner;
  expert::ObstacleMapInput map(owner);
  EXPECT_TRUE(map.empty());
  planners::ObstacleCells cells;
  cells.width = 20;
  cells.height = 10;
  cells.cells.assign(200, obstacle_map_t::CELL_UNKNOWN);
  const obstacle_map_t keyframe = planners::makeObstacleMap(cells, obstacle_map_t::ENCODING_RLE_ZSTD, 0, 0);
  ASSERT_TRUE(deliver(owner, channels::kObstacleMap.name, keyframe));
  planners::CellRect changed;
  ASSERT_TRUE(deliver(owner, channels::kObstacleMapChanges.name,
                      planners::makeMapChanges(cells.cells, 20, 10, changed, 0, 0, 0)));
  cells.cells[3 * 20 + 7] = obstacle_map_t::CELL_OCCUPIED;
  changed.include(7, 3);
  ASSERT_TRUE(deliver(owner, channels::kObstacleMapChanges.name,
                      planners::makeMapChanges(cells.cells, 20, 10, changed, 0, 100000, 1)));
  const auto at_0 = map.ofTick(0);
  ASSERT_NE(at_0, nullptr);
  EXPECT_EQ(at_0->at(7, 3), obstacle_map_t::CELL_UNKNOWN);
  const auto at_1 = map.ofTick(1);
  ASSERT_NE(at_1, nullptr);
  EXPECT_EQ(at_1->cells, cells.cells);
  const uint64_t version = map.version();
  EXPECT_EQ(map.latest(), at_1);  // the same map, not made again
  EXPECT_EQ(map.version(), version);
  // Tick 2's changes are missing: ask for them.
  EXPECT_TRUE(map.lacksTick(2));
  EXPECT_EQ(map.lackingChannel(2), channels::kObstacleMapChanges.name);
  // Changes that do not fit the map are refused with what is wrong.
  auto bad = planners::makeMapChanges(cells.cells, 20, 10, changed, 0, 200000, 2);
  bad.x0 = 20;  // one column past the map
  ASSERT_TRUE(deliver(owner, channels::kObstacleMapChanges.name, bad));
  EXPECT_THROW(map.ofTick(2), planners::ObstacleMapError);
}
