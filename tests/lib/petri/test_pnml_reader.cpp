// The PNML reader: the repository's nets, PNML variants, and every refusal
// with its file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "lib/petri/pnml_reader.hpp"

namespace beft::arbiter {
namespace {

const std::string kNets = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/";

// A small valid net, one element per line: line i of `lines` is line i + 3 of the text.
std::vector<std::string> baseLines() {
  return {
      R"(<place id="p_start"><initialMarking><text>1</text></initialMarking></place>)",          // 3
      R"(<place id="p_end"/>)",                                                                   // 4
      R"(<transition id="t_world"><toolspecific tool="beft" version="1"><expert>world</expert></toolspecific></transition>)",  // 5
      R"(<transition id="t_tick"><toolspecific tool="beft" version="1"><tick/></toolspecific></transition>)",  // 6
      R"(<arc id="a1" source="p_start" target="t_world"/>)",                                     // 7
      R"(<arc id="a2" source="t_world" target="p_end"/>)",                                       // 8
      R"(<arc id="a3" source="p_end" target="t_tick"/>)",                                        // 9
      R"(<arc id="a4" source="t_tick" target="p_start"/>)",                                      // 10
  };
}

std::string pnml(const std::vector<std::string>& lines) {
  std::string text = "<pnml>\n<net id=\"n\">\n";
  for (const auto& line : lines) text += line + "\n";
  return text + "</net>\n</pnml>\n";
}

std::vector<std::string> problemsOf(const std::string& text) {
  try {
    readPnmlString(text, "test.pnml");
  } catch (const NetError& e) {
    return e.problems();
  }
  return {};
}

// Exactly one problem, starting with "test.pnml:LINE: " and containing `fragment`.
void expectOneProblem(const std::string& text, int line, const std::string& fragment) {
  const auto problems = problemsOf(text);
  ASSERT_EQ(problems.size(), 1u) << (problems.empty() ? "no problem reported" : problems[0]);
  const std::string prefix = "test.pnml:" + std::to_string(line) + ": ";
  EXPECT_EQ(problems[0].rfind(prefix, 0), 0u) << problems[0];
  EXPECT_NE(problems[0].find(fragment), std::string::npos) << problems[0];
}

std::vector<std::string> withLine(int line, const std::string& replacement) {
  auto lines = baseLines();
  lines[line - 3] = replacement;
  return lines;
}

std::vector<std::string> plusLines(const std::vector<std::string>& extra) {
  auto lines = baseLines();
  lines.insert(lines.end(), extra.begin(), extra.end());
  return lines;
}

std::string transitionWith(const std::string& options) {
  return R"(<transition id="t_world"><toolspecific tool="beft" version="1">)" + options +
         "</toolspecific></transition>";
}

TEST(PnmlReader, ReadsTheBaseNet) {
  const Net net = readPnmlString(pnml(baseLines()), "test.pnml");
  ASSERT_EQ(net.places.size(), 2u);
  ASSERT_EQ(net.transitions.size(), 2u);
  EXPECT_EQ(net.initialMarking(), (Marking{1, 0}));
  EXPECT_EQ(net.transitions[0].expert, "world");
  EXPECT_FALSE(net.transitions[0].silent());
  EXPECT_TRUE(net.transitions[1].silent());
  EXPECT_EQ(net.tick_transition, 1);
  ASSERT_EQ(net.transitions[0].inputs.size(), 1u);
  EXPECT_EQ(net.transitions[0].inputs[0].place, 0);
  EXPECT_EQ(net.transitions[0].inputs[0].weight, 1);
  // Policy defaults when the net gives none.
  EXPECT_DOUBLE_EQ(net.transitions[0].policy.timeout_s, 10.0);
  EXPECT_EQ(net.transitions[0].policy.on_timeout, ExpiryAction::Fail);
  EXPECT_EQ(net.transitions[0].policy.retries, 0);
  EXPECT_TRUE(net.warnings.empty());
}

TEST(PnmlReader, ReadsTheDefaultNet) {
  const Net net = readPnmlFile(kNets + "default.pnml");
  // File order, which is firing order among transitions enabled together: vision leads the low level.
  EXPECT_EQ(net.experts(), (std::vector<std::string>{"world", "vision", "geometry", "audio", "visual_labels",
                                                     "acoustic_labels", "fusion", "dw", "exploration", "tasks"}));
  EXPECT_EQ(net.transitions[net.tick_transition].id, "t_next_tick");
  const Transition& vision = net.transitions[net.transitionIndex("t_vision")];
  EXPECT_EQ(vision.level, "low");
  EXPECT_DOUBLE_EQ(vision.policy.timeout_s, 5.0);
  EXPECT_EQ(vision.policy.on_timeout, ExpiryAction::Retry);
  EXPECT_EQ(vision.policy.on_failure, ExpiryAction::Retry);
  EXPECT_EQ(vision.policy.retries, 1);
  EXPECT_EQ(vision.policy.after_retries, ExpiryAction::Fail);
  EXPECT_EQ(net.transitions[net.transitionIndex("t_dw")].policy.after_retries, ExpiryAction::Skip);
  EXPECT_DOUBLE_EQ(net.transitions[net.transitionIndex("t_tasks")].policy.heartbeat_timeout_s, 5.0);
  EXPECT_TRUE(net.transitions[net.transitionIndex("t_low_done")].silent());
  // The world step forks to the three low-level experts; the join waits for all three.
  EXPECT_EQ(net.transitions[net.transitionIndex("t_world")].outputs.size(), 3u);
  EXPECT_EQ(net.transitions[net.transitionIndex("t_low_done")].inputs.size(), 3u);
  EXPECT_EQ(describeMarking(net, net.initialMarking()), "p_tick_start=1");
}

TEST(PnmlReader, FlattensNestedPages) {
  const Net net = readPnmlFile(kNets + "sequential.pnml");
  EXPECT_EQ(net.transitions.size(), 11u);
  EXPECT_EQ(net.places.size(), 11u);
  EXPECT_EQ(net.experts().size(), 10u);
  // One after the other: every expert transition has one input and one output.
  for (const auto& t : net.transitions) {
    EXPECT_EQ(t.inputs.size(), 1u) << t.id;
    EXPECT_EQ(t.outputs.size(), 1u) << t.id;
  }
}

TEST(PnmlReader, AcceptsValueLabelsWeightsAndReferences) {
  const Net net = readPnmlString(pnml({
      R"(<page id="pg"><place id="p_start"><initialMarking><value>2</value></initialMarking></place></page>)",
      R"(<place id="p_end"/>)",
      R"(<referencePlace id="rp_end" ref="p_end"/>)",
      R"(<transition id="t_world"><toolspecific tool="other"><x/></toolspecific><toolspecific tool="beft" version="1"><expert>world</expert></toolspecific></transition>)",
      R"(<transition id="t_join"><toolspecific tool="beft" version="1"><expert>-</expert></toolspecific></transition>)",
      R"(<transition id="t_tick"><toolspecific tool="beft"><tick/></toolspecific></transition>)",
      R"(<arc id="a1" source="p_start" target="t_world"><inscription><value>2</value></inscription></arc>)",
      R"(<arc id="a2" source="t_world" target="rp_end"><inscription><text> 3 </text></inscription></arc>)",
      R"(<arc id="a3" source="p_end" target="t_join"/>)",
      R"(<arc id="a4" source="t_join" target="p_start"/>)",
      R"(<arc id="a5" source="p_start" target="t_tick"/>)",
      R"(<arc id="a6" source="t_tick" target="p_start"/>)",
  }), "test.pnml");
  EXPECT_EQ(net.initialMarking(), (Marking{2, 0}));
  const Transition& world = net.transitions[net.transitionIndex("t_world")];
  EXPECT_EQ(world.inputs[0].weight, 2);
  ASSERT_EQ(world.outputs.size(), 1u);
  EXPECT_EQ(world.outputs[0].place, net.placeIndex("p_end"));  // through the reference
  EXPECT_EQ(world.outputs[0].weight, 3);
  EXPECT_TRUE(net.transitions[net.transitionIndex("t_join")].silent());
  EXPECT_EQ(net.experts(), std::vector<std::string>{"world"});
}

TEST(PnmlReader, ReadsPolicies) {
  const Net net = readPnmlString(pnml(withLine(5, transitionWith(
      "<expert>vision</expert><level>low</level><timeout>2.5</timeout>"
      "<heartbeat_timeout>1.5</heartbeat_timeout><on_timeout>retry</on_timeout>"
      "<on_failure>skip</on_failure><retries>3</retries><after_retries>skip</after_retries>"))),
                                 "test.pnml");
  const FiringPolicy& policy = net.transitions[0].policy;
  EXPECT_DOUBLE_EQ(policy.timeout_s, 2.5);
  EXPECT_DOUBLE_EQ(policy.heartbeat_timeout_s, 1.5);
  EXPECT_EQ(policy.on_timeout, ExpiryAction::Retry);
  EXPECT_EQ(policy.on_failure, ExpiryAction::Skip);
  EXPECT_EQ(policy.retries, 3);
  EXPECT_EQ(policy.after_retries, ExpiryAction::Skip);
  // A retry policy without <retries> retries once.
  const Net once = readPnmlString(
      pnml(withLine(5, transitionWith("<expert>vision</expert><on_timeout>retry</on_timeout>"))), "test.pnml");
  EXPECT_EQ(once.transitions[0].policy.retries, 1);
}

TEST(PnmlReader, RefusesUnknownArcEnds) {
  expectOneProblem(pnml(withLine(8, R"(<arc id="a2" source="t_world" target="p_nowhere"/>)")), 8,
                   "unknown target 'p_nowhere'");
  expectOneProblem(pnml(withLine(7, R"(<arc id="a1" source="p_gone" target="t_world"/>)")), 7,
                   "unknown source 'p_gone'");
}

TEST(PnmlReader, RefusesArcsBetweenNodesOfOneKind) {
  expectOneProblem(pnml(plusLines({R"(<arc id="a5" source="p_start" target="p_end"/>)"})), 11,
                   "joins place 'p_start' to place 'p_end'");
  expectOneProblem(pnml(plusLines({R"(<arc id="a5" source="t_world" target="t_tick"/>)"})), 11,
                   "joins transition 't_world' to transition 't_tick'");
}

TEST(PnmlReader, RefusesDuplicateIdsAndArcs) {
  expectOneProblem(pnml(plusLines({R"(<place id="p_end"/>)"})), 11, "duplicate id 'p_end' (first used at line 4)");
  expectOneProblem(pnml(plusLines({R"(<arc id="a5" source="p_start" target="t_world"/>)"})), 11,
                   "second arc from 'p_start' to 't_world' (first at line 7)");
}

TEST(PnmlReader, RefusesBadNumbers) {
  expectOneProblem(pnml(withLine(3, R"(<place id="p_start"><initialMarking><text>one</text></initialMarking></place>)")),
                   3, "initial marking 'one' of place 'p_start'");
  expectOneProblem(pnml(withLine(3, R"(<place id="p_start"><initialMarking><text>-1</text></initialMarking></place>)")),
                   3, "initial marking '-1'");
  expectOneProblem(pnml(withLine(7, R"(<arc id="a1" source="p_start" target="t_world"><inscription><text>0</text></inscription></arc>)")),
                   7, "weight '0' of arc 'a1'");
  expectOneProblem(pnml(withLine(7, R"(<arc id="a1" source="p_start" target="t_world"><inscription><text>1.5</text></inscription></arc>)")),
                   7, "weight '1.5'");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><timeout>fast</timeout>"))), 5,
                   "<timeout> of transition 't_world' is 'fast'");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><timeout>-2</timeout>"))), 5,
                   "is '-2'; expected seconds");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><timeout>nan</timeout>"))), 5,
                   "is 'nan'");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><on_timeout>retry</on_timeout><retries>many</retries>"))),
                   5, "<retries> of transition 't_world' is 'many'");
}

TEST(PnmlReader, RefusesTransitionsWithoutExpert) {
  expectOneProblem(pnml(withLine(5, R"(<transition id="t_world"><name><text>world</text></name></transition>)")), 5,
                   "transition 't_world' names no expert");
  expectOneProblem(pnml(withLine(5, transitionWith("<level>low</level>"))), 5, "names no expert");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert></expert>"))), 5, "names no expert");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>my vision</expert>"))), 5,
                   "expert name 'my vision'");
}

TEST(PnmlReader, RefusesUnknownOptionsAndBadPolicies) {
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><timout>2</timout>"))), 5,
                   "unknown element <timout>");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><on_timeout>ignore</on_timeout>"))), 5,
                   "is 'ignore'; expected retry, skip or fail");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><on_timeout>retry</on_timeout><after_retries>retry</after_retries>"))),
                   5, "expected skip or fail");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><retries>2</retries>"))), 5,
                   "neither <on_timeout> nor <on_failure> is retry");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><on_failure>retry</on_failure><retries>0</retries>"))),
                   5, "retry policy with <retries>0</retries>");
  expectOneProblem(pnml(withLine(5, transitionWith("<expert>world</expert><expert>vision</expert>"))), 5,
                   "<expert> given twice");
  expectOneProblem(pnml(withLine(6, R"(<transition id="t_tick"><toolspecific tool="beft" version="1"><tick/><timeout>1</timeout></toolspecific></transition>)")),
                   6, "is silent");
  expectOneProblem(pnml(withLine(5, R"(<transition id="t_world"><toolspecific tool="beft" version="2"><expert>world</expert></toolspecific></transition>)")),
                   5, "version '2' is not supported");
  expectOneProblem(pnml(withLine(3, R"(<place id="p_start"><initialMarking><text>1</text></initialMarking><toolspecific tool="beft"><tick_end/></toolspecific></place>)")),
                   3, "places take no beft options");
}

TEST(PnmlReader, RefusesAWrongTickTransition) {
  // None.
  expectOneProblem(pnml(withLine(6, R"(<transition id="t_tick"><toolspecific tool="beft"><silent/></toolspecific></transition>)")),
                   2, "no tick transition");
  // Two.
  expectOneProblem(pnml(plusLines({R"(<transition id="t_tick2"><toolspecific tool="beft"><tick/></toolspecific></transition>)",
                                   R"(<arc id="a5" source="p_end" target="t_tick2"/>)"})),
                   11, "second tick transition 't_tick2'");
  // One with an expert.
  expectOneProblem(pnml(withLine(6, R"(<transition id="t_tick"><toolspecific tool="beft"><tick/><expert>world</expert></toolspecific></transition>)")),
                   6, "the tick transition must be silent");
}

TEST(PnmlReader, RefusesATransitionWithoutInput) {
  expectOneProblem(pnml(plusLines({R"(<transition id="t_x"><toolspecific tool="beft"><expert>x</expert></toolspecific></transition>)",
                                   R"(<arc id="a5" source="t_x" target="p_end"/>)"})),
                   11, "transition 't_x' has no input place");
}

TEST(PnmlReader, ReportsMalformedXmlAndWrongDocuments) {
  // tinyxml2 names the line of the element left open.
  expectOneProblem("<pnml>\n<net id=\"n\">\n<place id=\"p\">\n</net>\n</pnml>\n", 3, "not well-formed XML");
  expectOneProblem("<?xml version=\"1.0\"?>\n<petrinet/>\n", 2, "root element is <petrinet>, expected <pnml>");
  expectOneProblem("<pnml>\n</pnml>\n", 1, "<pnml> holds no <net>");
  auto lines = baseLines();
  const std::string text = "<pnml>\n<net id=\"n\" type=\"http://www.pnml.org/version-2009/grammar/symmetricnet\">\n" +
                           [&] { std::string s; for (auto& l : lines) s += l + "\n"; return s; }() + "</net>\n</pnml>\n";
  expectOneProblem(text, 2, "is a high-level net, not a place/transition net");
}

TEST(PnmlReader, ReportsEveryProblemAtOnce) {
  auto lines = withLine(7, R"(<arc id="a1" source="p_start" target="t_nowhere"/>)");
  lines[5 - 3] = transitionWith("<expert>world</expert><timout>1</timout>");
  const auto problems = problemsOf(pnml(lines));
  // The option and the arc; not t_world's missing input, which the arc explains.
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("test.pnml:5: unknown element <timout>"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("test.pnml:7: arc 'a1': unknown target"), std::string::npos) << problems[1];
}

TEST(PnmlReader, ReportsAMissingFile) {
  try {
    readPnmlFile("no/such/net.pnml");
    FAIL() << "no error";
  } catch (const NetError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_NE(e.problems()[0].find("no/such/net.pnml: cannot open"), std::string::npos) << e.problems()[0];
  }
}

TEST(PnmlReader, WarnsAboutAnIsolatedPlace) {
  const Net net = readPnmlString(pnml(plusLines({R"(<place id="p_lonely"/>)"})), "test.pnml");
  ASSERT_EQ(net.warnings.size(), 1u);
  EXPECT_EQ(net.warnings[0], "test.pnml:11: place 'p_lonely' has no arcs");
}

}  // namespace
}  // namespace beft::arbiter
