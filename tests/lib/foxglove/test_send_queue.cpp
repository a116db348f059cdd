// The per-client send queue: its bound in bytes, latest-wins frames, the
// count of dropped frames, and control text that is never dropped.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/foxglove/send_queue.hpp"

using beft::foxglove::Frame;
using beft::foxglove::SendQueue;

namespace {

Frame data(const std::string& bytes, std::optional<uint32_t> key = std::nullopt) { return Frame{bytes, true, key}; }
Frame control(const std::string& bytes) { return Frame{bytes, false, std::nullopt}; }

std::vector<std::string> drain(SendQueue& queue) {
  std::vector<std::string> out;
  while (!queue.empty()) out.push_back(queue.pop().bytes);
  return out;
}

}  // namespace

TEST(SendQueue, KeepsOrderAndCountsBytes) {
  SendQueue queue(100);
  EXPECT_TRUE(queue.empty());
  queue.push(control("advertise"));
  queue.push(data("aaaa"));
  queue.push(data("bb"));
  EXPECT_EQ(queue.bytes(), 15u);
  EXPECT_EQ(queue.size(), 3u);
  EXPECT_EQ(queue.front().bytes, "advertise");
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"advertise", "aaaa", "bb"}));
  EXPECT_EQ(queue.bytes(), 0u);
  EXPECT_EQ(queue.takeDropped(), 0u);
  EXPECT_THROW(queue.pop(), std::logic_error);
}

TEST(SendQueue, DropsTheOldestDataFramesToStayWithinItsBound) {
  SendQueue queue(10);
  queue.push(data("1111"));
  queue.push(data("2222"));
  queue.push(data("3333"));  // 12 bytes: "1111" goes
  EXPECT_EQ(queue.bytes(), 8u);
  EXPECT_EQ(queue.takeDropped(), 1u);
  EXPECT_EQ(queue.takeDropped(), 0u);  // counted once
  queue.push(data("44444444"));  // 16 bytes: "2222" and "3333" go
  EXPECT_EQ(queue.takeDropped(), 2u);
  EXPECT_EQ(drain(queue), std::vector<std::string>{"44444444"});
}

TEST(SendQueue, NeverDropsControlText) {
  SendQueue queue(10);
  queue.push(control("serverInfo"));
  queue.push(data("aaaa"));
  queue.push(control("status!"));  // 21 bytes: only the data frame may go
  EXPECT_EQ(queue.takeDropped(), 1u);
  queue.push(control("advertise......"));  // control alone may exceed the bound
  EXPECT_EQ(queue.takeDropped(), 0u);
  EXPECT_GT(queue.bytes(), queue.maxBytes());
  queue.push(data("b"));  // the newest data frame goes when nothing older is droppable
  EXPECT_EQ(queue.takeDropped(), 1u);
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"serverInfo", "status!", "advertise......"}));
}

TEST(SendQueue, LatestWinsReplacesTheQueuedFrameOfItsKeyInPlace) {
  SendQueue queue(100);
  queue.push(data("camera-1", 7));
  queue.push(data("robot-1"));
  queue.push(data("map-1", 9));
  queue.push(data("camera-2-bigger", 7));
  queue.push(data("robot-2"));
  EXPECT_EQ(queue.takeReplaced(), 1u);
  EXPECT_EQ(queue.takeDropped(), 0u);
  EXPECT_EQ(queue.bytes(), std::string("camera-2-bigger" "robot-1" "map-1" "robot-2").size());
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"camera-2-bigger", "robot-1", "map-1", "robot-2"}));
  queue.push(data("camera-3", 7));  // nothing queued of key 7 any more
  EXPECT_EQ(queue.takeReplaced(), 0u);
  EXPECT_EQ(queue.size(), 1u);
}

TEST(SendQueue, AReplacementThatGrowsPastTheBoundDropsOlderFrames) {
  SendQueue queue(12);
  queue.push(data("aaaa"));
  queue.push(data("k1", 1));
  queue.push(data("bbbb"));
  queue.push(data("k1-longer", 1));  // 4 + 9 + 4 = 17: "aaaa" goes, then 13: "k1-longer" (oldest left) goes
  EXPECT_EQ(queue.takeReplaced(), 1u);
  EXPECT_EQ(queue.takeDropped(), 2u);
  EXPECT_EQ(drain(queue), std::vector<std::string>{"bbbb"});
}
