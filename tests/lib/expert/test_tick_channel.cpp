// Tick-indexed input ports: find the message of a firing's tick, not just
// the newest one.
#include <gtest/gtest.h>

#include <beft/robot_state_t.hpp>

#include "scene_builders.hpp"
#include "expert.hpp"

using namespace beft;

namespace {
// An expert with nothing but the port under test.
struct PortOwner : expert::Expert {
  std::string name() const override { return "owner"; }
  std::string description() const override { return "test"; }
  expert::Outcome fire(const expert::Firing&, expert::Output&) override { return expert::Outcome::success(); }
};
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

TEST(TickInput, ARepeatedTickGivesTheNewestCopy) {
  PortOwner owner;
  expert::TickInput<robot_state_t> channel(owner, channels::kRobotState);
  channel.store(test::robot(1, 0, 0, 0, 0, 2));
  channel.store(test::robot(2, 0, 0, 0, 0, 2));
  channel.store(test::robot(3, 0, 0, 0, 0, 3));
  ASSERT_NE(channel.ofTick(2), nullptr);
  EXPECT_DOUBLE_EQ(channel.ofTick(2)->x, 2);
}
