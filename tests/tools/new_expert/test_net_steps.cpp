// The net edits beft-new-expert prints, made on every shipped net for a new
// expert of each level: the net still reads as a schedule, the new expert
// fires right after its model and hands on what the model handed on, and the
// net stays as safe and free of deadlocks as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "lib/petri/net_analysis.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "tools/new_expert/net_steps.hpp"

namespace beft::new_expert {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

ExpertSpec specOfLevel(const std::string& level) {
  ExpertSpec spec;
  spec.name = "threat";
  spec.level = level;
  spec.after = usualExpertOfLevel(level);
  spec.source_root = BEFT_SOURCE_DIR;
  return spec;
}

std::vector<std::string> placeIds(const arbiter::Net& net, const std::vector<arbiter::ArcEnd>& ends) {
  std::vector<std::string> ids;
  for (const auto& end : ends) ids.push_back(net.places[end.place].id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

void checkEditedNet(const std::string& text, const std::string& file, const ExpertSpec& spec) {
  const NetEdit edit = planNetEdit(text, file, spec);
  ASSERT_FALSE(edit.model_expert.empty()) << "every shipped net has an expert of each level";
  const arbiter::Net before = arbiter::readPnmlString(text, file);
  const arbiter::Net after = arbiter::readPnmlString(applyNetEdit(text, edit), file + " (edited)");
  const int added = after.transitionIndex("t_" + spec.name);
  ASSERT_GE(added, 0);
  const auto& transition = after.transitions[added];
  EXPECT_EQ(transition.expert, spec.name);
  EXPECT_EQ(transition.level, before.transitions[before.transitionIndex(edit.model_transition)].level);
  EXPECT_EQ(placeIds(after, transition.inputs), std::vector<std::string>{"p_" + spec.name + "_in"});
  const auto& model_before = before.transitions[before.transitionIndex(edit.model_transition)];
  const auto& model_after = after.transitions[after.transitionIndex(edit.model_transition)];
  EXPECT_EQ(placeIds(after, model_after.outputs), std::vector<std::string>{"p_" + spec.name + "_in"});
  EXPECT_EQ(placeIds(after, transition.outputs), placeIds(before, model_before.outputs));
  EXPECT_EQ(after.transitions.size(), before.transitions.size() + 1);
  EXPECT_EQ(after.places.size(), before.places.size() + 1);

  const auto analysis_before = arbiter::analyseNet(before);
  const auto analysis_after = arbiter::analyseNet(after);
  ASSERT_TRUE(analysis_after.complete);
  EXPECT_EQ(analysis_after.safe(), analysis_before.safe());
  EXPECT_EQ(analysis_after.deadlock, analysis_before.deadlock);
  EXPECT_TRUE(analysis_after.fired[added]);
}

TEST(NetSteps, EveryShippedNetTakesANewExpertOfEachLevel) {
  int nets = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(BEFT_SOURCE_DIR) / "scenarios/nets")) {
    if (entry.path().extension() != ".pnml") continue;
    ++nets;
    const std::string text = readFile(entry.path());
    for (const char* level : {"low", "mid", "high"}) {
      SCOPED_TRACE(entry.path().filename().string() + ", " + level);
      checkEditedNet(text, entry.path().filename().string(), specOfLevel(level));
    }
  }
  EXPECT_GE(nets, 5);
}

TEST(NetSteps, PrintsTheLinesAsTheyAreInTheFile) {
  const fs::path file = fs::path(BEFT_SOURCE_DIR) / "scenarios/nets/default.pnml";
  const std::string text = readFile(file);
  const NetEdit edit = planNetEdit(text, "default.pnml", specOfLevel("high"));
  EXPECT_EQ(edit.model_expert, "dw");
  ASSERT_EQ(edit.arc_changes.size(), 1u);
  EXPECT_EQ(edit.arc_changes[0].before, "<arc id=\"a_dw_out\" source=\"t_dw\" target=\"p_exploration_in\"/>");
  EXPECT_EQ(edit.arc_changes[0].after, "<arc id=\"a_dw_out\" source=\"t_threat\" target=\"p_exploration_in\"/>");
  std::ifstream in(file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n == edit.arc_changes[0].line) {
      EXPECT_NE(line.find(edit.arc_changes[0].before), std::string::npos) << n;
    }
    if (n == edit.model_end_line) {
      EXPECT_NE(line.find("</transition>"), std::string::npos) << n;
    }
  }
  EXPECT_NE(edit.nodes.find("<expert>threat</expert><level>high</level>"), std::string::npos) << edit.nodes;
  EXPECT_EQ(edit.nodes.find("graphics"), std::string::npos) << edit.nodes;
}

TEST(NetSteps, ANetWithoutTheLevelIsLeftAsItIs) {
  ExpertSpec spec = specOfLevel("high");
  spec.level = "none_such";
  spec.after = "no_expert";
  const std::string text = readFile(fs::path(BEFT_SOURCE_DIR) / "scenarios/nets/sequential.pnml");
  const NetEdit edit = planNetEdit(text, "sequential.pnml", spec);
  EXPECT_TRUE(edit.model_expert.empty());
  EXPECT_EQ(applyNetEdit(text, edit), text);
}

}  // namespace
}  // namespace beft::new_expert
