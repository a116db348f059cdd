// External experts through the bridge (services/bridge/external_experts.hpp):
// an announced client's messages reach the bus as the LCM messages of their
// channels; a wrong field, a missing one, an undeclared channel or another
// expert's name is refused with a status naming it, and nothing is published.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <beft/dynamic_weights_t.hpp>
#include <nlohmann/json.hpp>

#include "lib/foxglove/protocol.hpp"
#include "services/bridge/external_experts.hpp"

using namespace beft;
using beft::bridge::ExternalExperts;

namespace {

class RecordingBus : public bridge::ExpertBus {
 public:
  std::string publish(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    sent.emplace_back(channel, bytes);
    return "";
  }
  void listPublished(beft::done_t& done) override {
    done.sender = 77;
    done.num_published = 1;
    done.published_channels = {"DYNAMIC_WEIGHTS"};
    done.published_sequences = {5};
  }
  std::vector<std::pair<std::string, std::vector<uint8_t>>> sent;
};

const char* kAnnouncement =
    R"({"protocol": 1, "name": "dw", "pid": 1, "host": "h",
        "reads": [{"channel": "AUDIO", "type": "beft.acoustic_percepts_t"}],
        "writes": [{"channel": "DYNAMIC_WEIGHTS", "type": "beft.dynamic_weights_t"}],
        "parameters": [], "resume_log": ""})";

const char* kWeights =
    R"({"utime": 100000, "tick": 1, "viewing_direction": null, "current_task": "idle", "attended_object": "",
        "num_weights": 1, "weights": [{"object_id": "siren", "weight": 0.5, "congruency": 0.5, "rising": false,
        "step": 0, "label": "siren", "activity": "ringing", "sounding": true}]})";

std::string done(const std::string& expert) {
  return R"({"utime": 100000, "expert": ")" + expert +
         R"(", "tick": 1, "firing_id": 3, "outcome": 0, "message": "", "duration": 0.001, "sender": 0,
             "num_published": 0, "published_channels": [], "published_sequences": []})";
}

class ExternalExpertsTest : public ::testing::Test {
 protected:
  RecordingBus bus;
  ExternalExperts experts{bus};
};

TEST_F(ExternalExpertsTest, AnAnnouncedExpertsOutputReachesTheBusAsItsLcmMessage) {
  const auto accepted = experts.announce(1, kAnnouncement);
  EXPECT_EQ(accepted.level, foxglove::kStatusInfo) << accepted.message;
  EXPECT_EQ(accepted.id, "beft.expert.dw");
  EXPECT_TRUE(experts.publish(1, "DYNAMIC_WEIGHTS", kWeights).message.empty());
  ASSERT_EQ(bus.sent.size(), 1u);
  EXPECT_EQ(bus.sent[0].first, "DYNAMIC_WEIGHTS");
  beft::dynamic_weights_t weights{};
  const auto& bytes = bus.sent[0].second;
  ASSERT_EQ(weights.decode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  EXPECT_EQ(weights.tick, 1);
  EXPECT_TRUE(std::isnan(weights.viewing_direction));
  ASSERT_EQ(weights.weights.size(), 1u);
  EXPECT_EQ(weights.weights[0].object_id, "siren");
}

TEST_F(ExternalExpertsTest, ADoneListsWhatTheBridgePublished) {
  experts.announce(1, kAnnouncement);
  EXPECT_TRUE(experts.publish(1, "DONE", done("dw")).message.empty());
  ASSERT_EQ(bus.sent.size(), 1u);
  beft::done_t answer{};
  const auto& bytes = bus.sent[0].second;
  ASSERT_GT(answer.decode(bytes.data(), 0, static_cast<int>(bytes.size())), 0);
  EXPECT_EQ(answer.sender, 77);
  EXPECT_EQ(answer.published_sequences, std::vector<int64_t>{5});
  EXPECT_EQ(answer.firing_id, 3);
}

TEST_F(ExternalExpertsTest, AWrongOrMissingFieldIsRefusedByNameAndNothingIsPublished) {
  experts.announce(1, kAnnouncement);
  std::string wrong_type = kWeights;
  wrong_type.replace(wrong_type.find("\"weight\": 0.5"), 13, "\"weight\": \"heavy\"");
  const auto refused = experts.publish(1, "DYNAMIC_WEIGHTS", wrong_type);
  EXPECT_EQ(refused.level, foxglove::kStatusError);
  EXPECT_NE(refused.message.find("weights[0].weight"), std::string::npos) << refused.message;
  std::string missing = kWeights;
  missing.replace(missing.find("\"tick\": 1, "), 11, "");
  const auto refused_missing = experts.publish(1, "DYNAMIC_WEIGHTS", missing);
  EXPECT_NE(refused_missing.message.find("tick"), std::string::npos) << refused_missing.message;
  EXPECT_TRUE(bus.sent.empty());
  EXPECT_EQ(experts.refused(), 2u);
}

TEST_F(ExternalExpertsTest, AnUndeclaredChannelOrAnotherExpertsNameIsRefused) {
  experts.announce(1, kAnnouncement);
  const auto undeclared = experts.publish(1, "TASK_COMMAND", "{}");
  EXPECT_NE(undeclared.message.find("TASK_COMMAND refused: expert dw does not declare it"), std::string::npos)
      << undeclared.message;
  const auto impostor = experts.publish(1, "DONE", done("fusion"));
  EXPECT_NE(impostor.message.find("expert: \"fusion\" is not dw"), std::string::npos) << impostor.message;
  EXPECT_NE(experts.publish(2, "DYNAMIC_WEIGHTS", kWeights).message.find("announce the expert"), std::string::npos);
  EXPECT_TRUE(bus.sent.empty());
}

TEST_F(ExternalExpertsTest, AnAnnouncementIsCheckedAgainstTheChannelTable) {
  EXPECT_EQ(experts.announce(1, kAnnouncement).level, foxglove::kStatusInfo);
  const auto twice = experts.announce(2, kAnnouncement);
  EXPECT_NE(twice.message.find("another client is expert dw"), std::string::npos) << twice.message;
  const auto control = experts.announce(
      3, R"({"name": "x", "reads": [], "writes": [{"channel": "FIRE", "type": "beft.fire_t"}]})");
  EXPECT_NE(control.message.find("writes[0]: FIRE is not a data channel"), std::string::npos) << control.message;
  const auto wrong_type = experts.announce(
      3, R"({"name": "x", "reads": [{"channel": "AUDIO", "type": "beft.labels_t"}], "writes": []})");
  EXPECT_NE(wrong_type.message.find("reads[0]: AUDIO carries beft.acoustic_percepts_t"), std::string::npos);
  experts.forget(1);
  EXPECT_EQ(experts.announce(2, kAnnouncement).level, foxglove::kStatusInfo);
  EXPECT_EQ(ExternalExperts::advertisable("DONE", "beft.done_t"), "");
  EXPECT_NE(ExternalExperts::advertisable("DONE", "beft.fire_t"), "");
}

TEST_F(ExternalExpertsTest, AnExpertRestartedMidRunGetsTheRunsHistoryBeforeItsAcceptance) {
  const std::string log = std::string(BEFT_SOURCE_DIR) + "/tests/system/data/peek_6_ticks.lcmlog";
  const std::string announcement = R"({"name": "geometry", "resume_log": ")" + log +
                                   R"(", "reads": [{"channel": "ROBOT_STATE", "type": "beft.robot_state_t"}],
                                   "writes": [{"channel": "GEOMETRY", "type": "beft.geometry_percepts_t"}]})";
  const auto accepted = experts.announce(1, announcement);
  ASSERT_EQ(accepted.level, foxglove::kStatusInfo) << accepted.message;
  const auto history = experts.takeHistory(1);
  std::size_t fires = 0, robot_states = 0;
  for (const auto& text : history) {
    const auto event = nlohmann::json::parse(text);
    EXPECT_EQ(event["op"], "beftHistory");
    const std::string channel = event["channel"];
    EXPECT_TRUE(channel == "FIRE" || channel == "DONE" || channel == "ROBOT_STATE") << channel;
    fires += channel == "FIRE";
    robot_states += channel == "ROBOT_STATE";
  }
  EXPECT_GT(fires, 0u);
  EXPECT_EQ(robot_states, 6u);
  EXPECT_TRUE(experts.takeHistory(1).empty());  // taken once
  const auto missing = experts.announce(2, R"({"name": "dw", "resume_log": "no/such.lcmlog", "reads": [],
                                              "writes": []})");
  EXPECT_EQ(missing.level, foxglove::kStatusError);
  EXPECT_NE(missing.message.find("resume_log"), std::string::npos) << missing.message;
}

}  // namespace

// Killed between an output and its DONE, a restarted expert runs the firing
// again: its identical output is on the bus already and is not sent twice;
// after its DONE, the next firing's outputs are published as ever.
TEST_F(ExternalExpertsTest, ARestartedExpertsRepeatedOutputIsNotPublishedTwice) {
  experts.announce(1, kAnnouncement);
  ASSERT_TRUE(experts.publish(1, "DYNAMIC_WEIGHTS", kWeights).message.empty());
  experts.forget(1);  // killed before its DONE
  ASSERT_EQ(experts.announce(2, kAnnouncement).level, foxglove::kStatusInfo);
  EXPECT_TRUE(experts.publish(2, "DYNAMIC_WEIGHTS", kWeights).message.empty());
  EXPECT_TRUE(experts.publish(2, "DONE", done("dw")).message.empty());
  ASSERT_EQ(bus.sent.size(), 2u);
  EXPECT_EQ(bus.sent[0].first, "DYNAMIC_WEIGHTS");
  EXPECT_EQ(bus.sent[1].first, "DONE");
  EXPECT_EQ(experts.resentTaken(), 1u);
  EXPECT_TRUE(experts.publish(2, "DYNAMIC_WEIGHTS", kWeights).message.empty());  // the next firing's
  EXPECT_EQ(bus.sent.size(), 3u);
}

// A restarted expert that computes something else this time publishes it:
// the bridge drops only byte-identical repeats.
TEST_F(ExternalExpertsTest, ARestartedExpertsDifferentOutputIsPublished) {
  experts.announce(1, kAnnouncement);
  experts.publish(1, "DYNAMIC_WEIGHTS", kWeights);
  experts.forget(1);
  experts.announce(2, kAnnouncement);
  std::string other = kWeights;
  other.replace(other.find("\"weight\": 0.5"), 13, "\"weight\": 0.7");
  EXPECT_TRUE(experts.publish(2, "DYNAMIC_WEIGHTS", other).message.empty());
  EXPECT_EQ(bus.sent.size(), 2u);
  EXPECT_EQ(experts.resentTaken(), 0u);
}

// An expert answered (DONE) before it died owes nothing again.
TEST_F(ExternalExpertsTest, AnExpertThatAnsweredBeforeItDiedOwesNothing) {
  experts.announce(1, kAnnouncement);
  experts.publish(1, "DYNAMIC_WEIGHTS", kWeights);
  experts.publish(1, "DONE", done("dw"));
  experts.forget(1);
  experts.announce(2, kAnnouncement);
  EXPECT_TRUE(experts.publish(2, "DYNAMIC_WEIGHTS", kWeights).message.empty());
  EXPECT_EQ(bus.sent.size(), 3u);
  EXPECT_EQ(experts.resentTaken(), 0u);
}
