// The blackboard process's logic without LCM: what it keeps, how it answers.
#include <gtest/gtest.h>

#include <vector>

#include <beft/bb_query_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/robot_state_t.hpp>

#include "blackboard/blackboard_service.hpp"

using beft::blackboard::BlackboardService;
using Verdict = BlackboardService::Verdict;

namespace {

std::vector<uint8_t> robotState(int64_t utime, double x) {
  beft::robot_state_t state{};
  state.utime = utime;
  state.x = x;
  std::vector<uint8_t> bytes(state.getEncodedSize());
  state.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

Verdict hear(BlackboardService& service, const std::string& channel, const std::vector<uint8_t>& bytes) {
  return service.onMessage(channel, bytes.data(), static_cast<int>(bytes.size()));
}

}  // namespace

TEST(BlackboardService, KeepsDataChannelsAndSkipsTheControlPlane) {
  BlackboardService service(BlackboardService::Options{});
  const auto bytes = robotState(100, 1);
  EXPECT_EQ(hear(service, "ROBOT_STATE", bytes), Verdict::StoredNewChannel);
  EXPECT_EQ(hear(service, "ROBOT_STATE", bytes), Verdict::Stored);
  EXPECT_EQ(hear(service, "FIRE", bytes), Verdict::Excluded);
  EXPECT_EQ(hear(service, "HEARTBEAT", bytes), Verdict::Excluded);
  EXPECT_EQ(hear(service, "BB_SNAPSHOT_x", bytes), Verdict::Excluded);
  EXPECT_EQ(hear(service, "LCM_SELF_TEST", std::vector<uint8_t>(13, 0)), Verdict::Ignored);
  EXPECT_EQ(hear(service, "ODD", std::vector<uint8_t>(9, 0)), Verdict::Rejected);
  EXPECT_EQ(service.store().channels(), std::vector<std::string>{"ROBOT_STATE"});
  EXPECT_EQ(service.messagesExcluded(), 3u);
}

TEST(BlackboardService, ServiceChannelsAreNeverStoredWhateverTheExclusions) {
  BlackboardService::Options options;
  options.exclude = {"CAMERA_.*"};  // replaces the default list
  BlackboardService service(options);
  const auto bytes = robotState(100, 1);
  EXPECT_EQ(hear(service, "BB_QUERY", bytes), Verdict::Excluded);
  EXPECT_EQ(hear(service, "BB_SNAPSHOT_vision", bytes), Verdict::Excluded);
  EXPECT_EQ(hear(service, "CAMERA_DEPTH", bytes), Verdict::Excluded);
  EXPECT_EQ(hear(service, "ROBOT_STATE_COPY", bytes), Verdict::StoredNewChannel);  // any beft type off the list
  beft::fire_t fire{};
  fire.expert = "world";
  std::vector<uint8_t> fire_bytes(fire.getEncodedSize());
  fire.encode(fire_bytes.data(), 0, static_cast<int>(fire_bytes.size()));
  EXPECT_EQ(hear(service, "FIRE", fire_bytes), Verdict::StoredNewChannel);  // not excluded any more
  EXPECT_EQ(hear(service, "FIRE", bytes), Verdict::Rejected);               // but only what FIRE carries
}

TEST(BlackboardService, AnswersToTheRequestersChannelWithTheLatest) {
  BlackboardService service(BlackboardService::Options{});
  hear(service, "ROBOT_STATE", robotState(100, 1));
  hear(service, "ROBOT_STATE", robotState(200, 2));
  beft::bb_query_t query{};
  query.requester = "fusion_12";
  query.query_id = 9;
  query.channels = {"ROBOT_STATE", "AUDIO"};
  query.num_channels = 2;
  const auto answer = service.answer(query, 5);
  ASSERT_TRUE(answer.has_value());
  EXPECT_EQ(answer->channel, "BB_SNAPSHOT_fusion_12");
  EXPECT_EQ(answer->snapshot.query_id, 9);
  ASSERT_EQ(answer->snapshot.entries.size(), 1u);
  EXPECT_EQ(answer->snapshot.entries[0].sequence, 2);
  EXPECT_EQ(answer->snapshot.entries[0].utime, 200);
  EXPECT_EQ(answer->missing, std::vector<std::string>{"AUDIO"});
  EXPECT_EQ(service.queriesAnswered(), 1u);
  EXPECT_NE(service.statusLine().find("1 channels, 2 messages stored"), std::string::npos) << service.statusLine();
}

TEST(BlackboardService, AQueryWithoutRequesterIsRefusedWithAReason) {
  BlackboardService service(BlackboardService::Options{});
  beft::bb_query_t query{};
  query.query_id = 3;
  std::string why;
  EXPECT_FALSE(service.answer(query, 0, &why).has_value());
  EXPECT_NE(why.find("no requester"), std::string::npos);
  EXPECT_EQ(service.queriesAnswered(), 0u);
}
