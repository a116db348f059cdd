// From a drawn net to a schedule: the annotations written into the
// editor's file, everything else kept, and the result run by the checks.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "tools/net_annotate/pnml_annotation.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "tests/system/run_support.hpp"

namespace {

using namespace beft;

const std::string kDrawn = std::string(BEFT_TEST_NETS_DIR) + "/ptnets/cycle_drawn.pnml";

std::string fileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

net_annotate::AnnotationRequest cycleRequest() {
  net_annotate::AnnotationRequest request;
  request.experts = {{"t0", "world"}, {"look", "vision"}};  // by id and by name
  request.tick = "next";
  request.levels = {{"t0", "world"}};
  return request;
}

TEST(NetAnnotate, MakesADrawnNetASchedule) {
  const auto result = net_annotate::annotatePnml(fileText(kDrawn), "cycle_drawn.pnml", cycleRequest());
  EXPECT_TRUE(result.made_silent.empty());
  const arbiter::Net net = arbiter::readPnmlString(result.text, "annotated.pnml");  // as the arbiter reads it
  EXPECT_EQ(net.experts(), (std::vector<std::string>{"world", "vision"}));
  EXPECT_EQ(net.transitions[net.tick_transition].id, "t2");
  EXPECT_EQ(net.transitions[0].level, "world");
  // What the editor wrote stays: graphics, names, the other tool's data, the comment.
  EXPECT_NE(result.text.find("<position x=\"40\" y=\"40\"/>"), std::string::npos);
  EXPECT_NE(result.text.find("<toolspecific tool=\"SomeEditor\" version=\"2\">"), std::string::npos);
  EXPECT_NE(result.text.find("<colour>blue</colour>"), std::string::npos);
  EXPECT_NE(result.text.find("A cycle as drawn in an editor"), std::string::npos);
  EXPECT_EQ(net.places[0].name, "tick start");
}

TEST(NetAnnotate, AnnotatingTwiceReplacesTheOldAnnotation) {
  const auto once = net_annotate::annotatePnml(fileText(kDrawn), "a.pnml", cycleRequest());
  net_annotate::AnnotationRequest again;
  again.experts = {{"t1", "audio"}};
  again.tick = "t2";
  const auto twice = net_annotate::annotatePnml(once.text, "b.pnml", again);
  EXPECT_EQ(twice.kept, (std::vector<std::string>{"t0"}));
  const arbiter::Net net = arbiter::readPnmlString(twice.text, "b.pnml");
  EXPECT_EQ(net.experts(), (std::vector<std::string>{"world", "audio"}));
  size_t count = 0;
  for (size_t at = twice.text.find("tool=\"beft\""); at != std::string::npos; at = twice.text.find("tool=\"beft\"", at + 1))
    ++count;
  EXPECT_EQ(count, 3u);  // one per transition, none left over
}

TEST(NetAnnotate, TransitionsNotNamedBecomeSilentAndAreListed) {
  net_annotate::AnnotationRequest request;
  request.experts = {{"t0", "world"}};
  request.tick = "t2";
  const auto result = net_annotate::annotatePnml(fileText(kDrawn), "a.pnml", request);
  EXPECT_EQ(result.made_silent, (std::vector<std::string>{"t1"}));
  EXPECT_TRUE(arbiter::readPnmlString(result.text, "a.pnml").transitions[1].silent());
}

TEST(NetAnnotate, RefusesWhatItCannotDoWithTheReason) {
  const std::string text = fileText(kDrawn);
  const auto refusal = [&](const net_annotate::AnnotationRequest& request) {
    try {
      net_annotate::annotatePnml(text, "c.pnml", request);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  net_annotate::AnnotationRequest unknown = cycleRequest();
  unknown.experts["nowhere"] = "fusion";
  EXPECT_NE(refusal(unknown).find("no transition with id or name 'nowhere'"), std::string::npos);
  net_annotate::AnnotationRequest twice = cycleRequest();
  twice.silent = {"t0"};
  EXPECT_NE(refusal(twice).find("c.pnml:16: transition 't0' is given two roles"), std::string::npos) << refusal(twice);
  std::string same_names = text;
  same_names.replace(same_names.find("<text>next</text>"), 17, "<text>look</text>");
  net_annotate::AnnotationRequest ambiguous;
  ambiguous.experts = {{"look", "vision"}};
  ambiguous.tick = "t0";
  try {
    net_annotate::annotatePnml(same_names, "c.pnml", ambiguous);
    ADD_FAILURE() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("two transitions are named 'look'"), std::string::npos) << e.what();
  }
}

TEST(NetAnnotateProcess, WritesTheFileAndTheCheckRunsIt) {
  using namespace beft::system_test;
  const std::string dir = makeTempDir("net_annotate");
  const std::string out = dir + "/schedule.pnml";
  const ProgramResult annotate = runCommand(binDir() + "/beft-net-annotate " + kDrawn +
                                                " --expert t0=world --expert look=vision --tick next --out " + out, 60);
  ASSERT_EQ(annotate.exit_code, 0) << annotate.output;
  EXPECT_NE(annotate.output.find("a schedule of 2 experts (world, vision)"), std::string::npos) << annotate.output;
  const ProgramResult check = runCommand(binDir() + "/beft-net-check " + out, 60);
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("result: OK, 1-safe and live"), std::string::npos) << check.output;
  // An expert name the arbiter refuses: the file is still written, and the problem said.
  const ProgramResult bad_name = runCommand(binDir() + "/beft-net-annotate " + kDrawn +
                                                " --expert 't0=two words' --expert look=vision --tick next --out " + out, 60);
  EXPECT_EQ(bad_name.exit_code, 1) << bad_name.output;
  EXPECT_NE(bad_name.output.find("not yet a schedule the arbiter can run"), std::string::npos) << bad_name.output;
  EXPECT_NE(bad_name.output.find("expert name 'two words'"), std::string::npos) << bad_name.output;
  const ProgramResult bad = runCommand(binDir() + "/beft-net-annotate " + kDrawn + " --expert t0 --tick t2 --out " + out, 60);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("'t0' is not TRANSITION=VALUE"), std::string::npos) << bad.output;
}

}  // namespace
