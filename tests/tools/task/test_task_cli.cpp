// beft-task's argument parsing and stack printing.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "tools/task/task_cli.hpp"
#include "lib/task/task_messages.hpp"

namespace beft::task_cli {
namespace {

TEST(TaskCli, ParsesEachBuiltInKind) {
  auto go = parsePush("goto", {"12", "8", "90"});
  EXPECT_EQ(go.kind, "goto");
  EXPECT_DOUBLE_EQ(go.x, 12);
  EXPECT_DOUBLE_EQ(go.y, 8);
  EXPECT_DOUBLE_EQ(go.yaw, 90);
  EXPECT_TRUE(std::isnan(parsePush("goto", {"1.5", "-2"}).yaw)) << "no yaw: any heading";
  EXPECT_DOUBLE_EQ(parsePush("turn_head", {"-45"}).yaw, -45);
  EXPECT_DOUBLE_EQ(parsePush("turn", {"180"}).yaw, 180);
  EXPECT_DOUBLE_EQ(parsePush("wait", {"2.5"}).x, 2.5);
  auto look = parsePush("look_at", {"victim1"});
  EXPECT_EQ(look.object_id, "victim1");
  EXPECT_TRUE(std::isnan(look.x)) << "no fallback position";
  auto point = parsePush("look_at", {"3", "4"});
  EXPECT_TRUE(point.object_id.empty());
  EXPECT_DOUBLE_EQ(point.y, 4);
}

TEST(TaskCli, CompositeKindsTakeAnOptionalObjectAndPosition) {
  auto verify = parsePush("verify", {"victim2"});
  EXPECT_EQ(verify.kind, "verify");
  EXPECT_EQ(verify.object_id, "victim2");
  auto approach = parsePush("approach", {"victim2", "4", "5", "90"});
  EXPECT_DOUBLE_EQ(approach.x, 4);
  EXPECT_DOUBLE_EQ(approach.yaw, 90);
  auto explore = parsePush("explore", {});
  EXPECT_TRUE(explore.object_id.empty());
  EXPECT_THROW(parsePush("explore", {"1"}), std::invalid_argument);
}

TEST(TaskCli, RefusesBadArgumentsSayingWhich) {
  try {
    parsePush("goto", {"12", "eight"});
    FAIL() << "accepted a word as a number";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("goto Y"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("eight"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parsePush("goto", {"12"}), std::invalid_argument);
  EXPECT_THROW(parsePush("goto", {"1", "2", "3", "4"}), std::invalid_argument);
  EXPECT_THROW(parsePush("goto", {"nan", "2"}), std::invalid_argument);
  EXPECT_THROW(parsePush("goto", {"1e999", "2"}), std::invalid_argument);
  EXPECT_THROW(parsePush("wait", {"-1"}), std::invalid_argument);
  EXPECT_THROW(parsePush("turn", {}), std::invalid_argument);
  EXPECT_THROW(parsePush("look_at", {"5"}), std::invalid_argument);
  EXPECT_THROW(parsePush("", {}), std::invalid_argument);
  EXPECT_THROW(parseNumber("3x", "X"), std::invalid_argument);
  EXPECT_DOUBLE_EQ(parseNumber("-3.25", "X"), -3.25);
}

beft::task_stack_t sampleStack() {
  tasks::TaskStack stack;
  tasks::Task go;
  go.kind = "goto";
  go.x = 12;
  go.y = 8;
  go.yaw = 90;
  go.priority = 50;
  go.origin = "user";
  stack.push(go);
  tasks::Task look;
  look.kind = "look_at";
  look.object_id = "victim1";
  look.priority = 100;
  look.origin = "dw";
  look.note = "turn-to reflex: victim1 weight 0.75";
  stack.push(look);
  return tasks::stackMessage(stack, 12300000, 123);
}

TEST(TaskCli, FormatsTheStackTopFirst) {
  const std::string text = formatStack(sampleStack());
  EXPECT_NE(text.find("t = 12.30 s (tick 123): 2 tasks"), std::string::npos) << text;
  const auto look = text.find("look_at(victim1)");
  const auto go = text.find("goto(12, 8, 90)");
  ASSERT_NE(look, std::string::npos) << text;
  ASSERT_NE(go, std::string::npos) << text;
  EXPECT_LT(look, go) << "top first";
  EXPECT_NE(text.find("active"), std::string::npos);
  EXPECT_NE(text.find("suspended"), std::string::npos);
  EXPECT_NE(text.find("turn-to reflex"), std::string::npos);

  beft::task_stack_t empty{};
  empty.utime = 0;
  empty.tick = 0;
  empty.num_tasks = 0;
  EXPECT_NE(formatStack(empty).find("empty"), std::string::npos);
}

TEST(TaskCli, StackAsJson) {
  const auto json = nlohmann::json::parse(stackJson(sampleStack()));
  EXPECT_EQ(json["tick"], 123);
  ASSERT_EQ(json["tasks"].size(), 2u);
  EXPECT_EQ(json["tasks"][0]["kind"], "look_at");
  EXPECT_EQ(json["tasks"][0]["status"], "active");
  EXPECT_EQ(json["tasks"][1]["yaw"], 90.0);
}

}  // namespace
}  // namespace beft::task_cli
