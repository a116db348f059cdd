// The control topics' payloads: untrusted bytes into requests, or into what was wrong.
#include <gtest/gtest.h>

#include "services/bridge/control_requests.hpp"

using namespace beft::bridge;

TEST(ControlRequests, ReadsEachTopic) {
  auto run = parseControlRequest(kRunControlTopic, R"({"action":"step"})");
  ASSERT_TRUE(std::holds_alternative<RunControlRequest>(run.request)) << run.error;
  EXPECT_EQ(std::get<RunControlRequest>(run.request).action, RunControlRequest::Action::kStep);

  auto go = parseControlRequest(kTaskTopic, R"({"action":"goto","x":12.5,"y":-3,"yaw":90})");
  ASSERT_TRUE(std::holds_alternative<TaskRequest>(go.request)) << go.error;
  const auto& task = std::get<TaskRequest>(go.request);
  EXPECT_EQ(task.action, TaskRequest::Action::kGoto);
  EXPECT_DOUBLE_EQ(task.x, 12.5);
  EXPECT_DOUBLE_EQ(task.y, -3);
  ASSERT_TRUE(task.yaw_deg);
  EXPECT_DOUBLE_EQ(*task.yaw_deg, 90);
  EXPECT_FALSE(std::get<TaskRequest>(parseControlRequest(kTaskTopic, R"({"action":"goto","x":1,"y":2})").request).yaw_deg);

  auto look = parseControlRequest(kTaskTopic, R"({"action":"look_at","object_id":"victim1"})");
  ASSERT_TRUE(std::holds_alternative<TaskRequest>(look.request)) << look.error;
  EXPECT_EQ(std::get<TaskRequest>(look.request).object_id, "victim1");

  auto seek = parseControlRequest(kPlaybackTopic, R"({"action":"seek","time_ns":1500000000})");
  ASSERT_TRUE(std::holds_alternative<PlaybackRequest>(seek.request)) << seek.error;
  EXPECT_EQ(*std::get<PlaybackRequest>(seek.request).time_ns, 1500000000);
  auto play = parseControlRequest(kPlaybackTopic, R"({"action":"play","speed":4})");
  ASSERT_TRUE(std::holds_alternative<PlaybackRequest>(play.request)) << play.error;
  EXPECT_DOUBLE_EQ(*std::get<PlaybackRequest>(play.request).speed, 4);
}

TEST(ControlRequests, SaysWhatIsWrong) {
  const auto error = [](const char* topic, const char* payload) {
    const auto parsed = parseControlRequest(topic, payload);
    EXPECT_TRUE(std::holds_alternative<std::monostate>(parsed.request)) << payload;
    return parsed.error;
  };
  EXPECT_NE(error(kTaskTopic, "{not json").find("not a JSON object"), std::string::npos);
  EXPECT_NE(error(kTaskTopic, "[1,2]").find("not a JSON object"), std::string::npos);
  EXPECT_NE(error(kTaskTopic, R"({"x":1})").find("action"), std::string::npos);
  EXPECT_NE(error(kTaskTopic, R"({"action":"fly"})").find("unknown action \"fly\""), std::string::npos);
  EXPECT_NE(error(kTaskTopic, R"({"action":"goto","x":"1","y":2})").find("\"x\""), std::string::npos);
  EXPECT_NE(error(kTaskTopic, R"({"action":"goto","x":1e300,"y":2})").find("out of range"), std::string::npos);
  EXPECT_NE(error(kTaskTopic, R"({"action":"look_at"})").find("object_id"), std::string::npos);
  EXPECT_NE(error(kRunControlTopic, R"({"action":"rewind"})").find("rewind"), std::string::npos);
  EXPECT_NE(error(kPlaybackTopic, R"({"action":"seek"})").find("time_ns"), std::string::npos);
  EXPECT_NE(error(kPlaybackTopic, R"({"action":"play","speed":-1})").find("speed"), std::string::npos);
  EXPECT_NE(error("/other", R"({"action":"play"})").find("not a control topic"), std::string::npos);
  EXPECT_FALSE(error(kTaskTopic, std::string("\xff\xfe\x00", 3).c_str()).empty());
}
