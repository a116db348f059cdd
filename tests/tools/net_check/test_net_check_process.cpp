// beft-net-check as a program: the JSON object for nets checked by hand,
// a cut search, and a schedule's own checks.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "tests/system/run_support.hpp"

namespace {

using namespace beft::system_test;
using nlohmann::json;

const std::string kPtNets = std::string(BEFT_TEST_NETS_DIR) + "/ptnets/";

json checkJson(const std::string& arguments, int expected_exit = 0) {
  const ProgramResult run = runCommand(binDir() + "/beft-net-check --json " + arguments + " 2>/dev/null", 120);
  EXPECT_EQ(run.exit_code, expected_exit) << run.output;
  try {
    return json::parse(run.output);
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not JSON: " << run.output;
    return json::object();
  }
}

TEST(NetCheckJson, HasEveryKeyTheIssueNames) {
  const json result = checkJson(kPtNets + "mutex.pnml");
  for (const char* key : {"places", "transitions", "arcs", "markings", "complete", "bounded", "max_tokens", "safe",
                          "deadlock", "deadlock_trace", "dead_transitions", "reversible"})
    EXPECT_TRUE(result.contains(key)) << key;
  EXPECT_EQ(result["places"], 5);
  EXPECT_EQ(result["transitions"], 4);
  EXPECT_EQ(result["arcs"], 12);
  EXPECT_EQ(result["markings"], 3);
  EXPECT_EQ(result["complete"], true);
  EXPECT_EQ(result["bounded"], true);
  EXPECT_EQ(result["max_tokens"], 1);
  EXPECT_EQ(result["safe"], true);
  EXPECT_EQ(result["deadlock"], false);
  EXPECT_TRUE(result["deadlock_trace"].is_null());
  EXPECT_EQ(result["dead_transitions"], json::array());
  EXPECT_EQ(result["reversible"], true);
  EXPECT_TRUE(result["schedule"].is_null());
}

TEST(NetCheckJson, PinsTheHandCheckedNets) {
  const json philosophers = checkJson(kPtNets + "philosophers2.pnml");
  EXPECT_EQ(philosophers["deadlock"], true);
  EXPECT_EQ(philosophers["deadlock_trace"], json::array({"take_left0", "take_left1"}));
  EXPECT_EQ(philosophers["reversible"], false);
  EXPECT_EQ(philosophers["markings"], 6);

  const json buffer = checkJson(kPtNets + "producer_consumer.pnml");
  EXPECT_EQ(buffer["max_tokens"], 2);
  EXPECT_EQ(buffer["safe"], false);
  EXPECT_EQ(buffer["max_tokens_per_place"]["buffer"], 2);
  EXPECT_EQ(buffer["reversible"], true);

  const json generator = checkJson(kPtNets + "generator.pnml");
  EXPECT_EQ(generator["bounded"], false);
  EXPECT_EQ(generator["complete"], false);
  EXPECT_TRUE(generator["max_tokens"].is_null());
  EXPECT_TRUE(generator["max_tokens_per_place"]["out"].is_null());
  EXPECT_EQ(generator["unbounded_witness"]["trace"], json::array({"emit"}));
  EXPECT_EQ(generator["unbounded_witness"]["growing_places"], json::array({"out"}));
  EXPECT_EQ(generator["deadlock_trace"], json::array({"stop"}));
  EXPECT_EQ(generator["dead_transitions"], json::array());
}

TEST(NetCheckJson, ACutSearchSaysItIsIncompleteAndWhatItLearned) {
  const json cut = checkJson(kPtNets + "producer_consumer.pnml --max-markings 5");
  EXPECT_EQ(cut["complete"], false);
  EXPECT_EQ(cut["markings"], 5);
  // The coverability graph (12 nodes here) decides the bounds and the dead
  // transitions; reversibility and deadlocks stay unknown.
  EXPECT_EQ(cut["bounded"], true);
  EXPECT_EQ(cut["max_tokens"], 2);
  EXPECT_EQ(cut["dead_transitions"], json::array());
  EXPECT_TRUE(cut["reversible"].is_null());
  EXPECT_TRUE(cut["deadlock"].is_null());
  const ProgramResult text = runCommand(binDir() + "/beft-net-check " + kPtNets + "producer_consumer.pnml --max-markings 5", 60);
  EXPECT_NE(text.output.find("INCOMPLETE: stopped at --max-markings 5"), std::string::npos) << text.output;
}

TEST(NetCheckJson, AScheduleGetsTheBeftChecksSeparately) {
  const json ok = checkJson(sourceDir() + "/scenarios/nets/default.pnml");
  EXPECT_EQ(ok["schedule"]["ok"], true);
  EXPECT_EQ(ok["schedule"]["states"], 46);
  EXPECT_EQ(ok["markings"], 17);  // the standard firing rule: an expert transition is one step
  const json unsafe = checkJson(std::string(BEFT_TEST_NETS_DIR) + "/unsafe.pnml", 1);
  EXPECT_EQ(unsafe["schedule"]["ok"], false);
  EXPECT_EQ(unsafe["schedule"]["safe"], false);
}

TEST(NetCheckText, AnUnreadableNetExitsTwoWithFileAndLine) {
  const ProgramResult run = runCommand(binDir() + "/beft-net-check " + std::string(BEFT_TEST_NETS_DIR) + "/bad_arc.pnml", 60);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("bad_arc.pnml:9: arc 'a2': unknown target 'p_missing'"), std::string::npos) << run.output;
}

}  // namespace
