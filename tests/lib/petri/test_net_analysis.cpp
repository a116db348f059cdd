// Analysis of any P/T net, pinned on nets small enough to check by hand
// (tests/lib/petri/nets/ptnets/, each file says what it holds).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/petri/coverability.hpp"
#include "lib/petri/net_analysis.hpp"
#include "lib/petri/pnml_reader.hpp"

namespace beft::arbiter {
namespace {

const std::string kPtNets = std::string(BEFT_TEST_NETS_DIR) + "/ptnets/";

Net anyNet(const std::string& file) {
  PnmlReadOptions options;
  options.schedule = false;
  return readPnmlFile(kPtNets + file, options);
}

std::vector<std::string> ids(const Net& net, const std::vector<int>& transitions) {
  std::vector<std::string> out;
  for (int t : transitions) out.push_back(net.transitions[t].id);
  return out;
}

int placeBound(const Net& net, const NetAnalysis& analysis, const std::string& place) {
  const auto& bound = analysis.place_bounds->at(net.placeIndex(place));
  return bound ? *bound : -1;
}

TEST(NetAnalysis, MutualExclusionIsSafeLiveAndReversible) {
  const Net net = anyNet("mutex.pnml");
  const NetAnalysis analysis = analyseNet(net);
  EXPECT_EQ(analysis.markings, 3u);
  EXPECT_EQ(analysis.edges, 4u);
  EXPECT_TRUE(analysis.complete);
  EXPECT_EQ(analysis.bounded, true);
  EXPECT_EQ(analysis.bound(), 1);
  EXPECT_EQ(analysis.safe(), true);
  EXPECT_EQ(analysis.deadlock, false);
  ASSERT_TRUE(analysis.dead_transitions);
  EXPECT_TRUE(analysis.dead_transitions->empty());
  EXPECT_EQ(analysis.reversible, true);
  // Never both in the critical section.
  EXPECT_EQ(placeBound(net, analysis, "crit1"), 1);
  EXPECT_EQ(analysis.coverability_nodes, 0u);
}

TEST(NetAnalysis, PhilosophersDeadlockWhenBothHoldTheirLeftFork) {
  const Net net = anyNet("philosophers2.pnml");
  const NetAnalysis analysis = analyseNet(net);
  EXPECT_EQ(analysis.markings, 6u);
  EXPECT_EQ(analysis.safe(), true);
  ASSERT_EQ(analysis.deadlock, true);
  EXPECT_EQ(ids(net, analysis.deadlock_trace), (std::vector<std::string>{"take_left0", "take_left1"}));
  Marking expected(net.places.size(), 0);
  expected[net.placeIndex("has_left0")] = 1;
  expected[net.placeIndex("has_left1")] = 1;
  EXPECT_EQ(analysis.deadlock_marking, expected);
  EXPECT_TRUE(analysis.dead_transitions->empty());
  EXPECT_EQ(analysis.reversible, false);
}

TEST(NetAnalysis, ProducerConsumerIsTwoSafeNotOneSafe) {
  const Net net = anyNet("producer_consumer.pnml");
  const NetAnalysis analysis = analyseNet(net);
  EXPECT_EQ(analysis.markings, 12u);
  EXPECT_EQ(analysis.bound(), 2);
  EXPECT_EQ(analysis.safe(), false);
  EXPECT_EQ(placeBound(net, analysis, "buffer"), 2);
  EXPECT_EQ(placeBound(net, analysis, "free"), 2);
  EXPECT_EQ(placeBound(net, analysis, "produce"), 1);
  EXPECT_EQ(analysis.deadlock, false);
  EXPECT_EQ(analysis.reversible, true);
}

TEST(NetAnalysis, AnUnboundedGeneratorGetsAWitnessThatRepeats) {
  const Net net = anyNet("generator.pnml");
  NetAnalysisOptions options;
  options.max_markings = 5000;
  const NetAnalysis analysis = analyseNet(net, options);
  EXPECT_FALSE(analysis.complete);
  EXPECT_EQ(analysis.bounded, false);
  ASSERT_TRUE(analysis.unbounded_witness);
  const auto& witness = *analysis.unbounded_witness;
  EXPECT_EQ(ids(net, witness.trace), (std::vector<std::string>{"emit"}));
  EXPECT_EQ(witness.covered_after, 0u);
  ASSERT_EQ(witness.growing_places.size(), 1u);
  EXPECT_EQ(net.places[witness.growing_places[0]].id, "out");
  // Replaying the witness reaches what it says, and it covers the earlier marking.
  Marking m = net.initialMarking();
  for (size_t i = 0; i < witness.trace.size(); ++i) {
    if (i == witness.covered_after) {
      EXPECT_EQ(m, witness.covered);
    }
    const Transition& t = net.transitions[witness.trace[i]];
    ASSERT_TRUE(isEnabled(t, m));
    consumeInputs(t, m);
    produceOutputs(t, m);
  }
  EXPECT_EQ(m, witness.covering);
  // The search goes on a little after the proof: it stops well before its budget.
  EXPECT_LT(analysis.markings, 200u);
  // The coverability graph decides the rest.
  EXPECT_EQ(placeBound(net, analysis, "out"), -1);
  EXPECT_EQ(placeBound(net, analysis, "on"), 1);
  EXPECT_EQ(analysis.bound(), std::nullopt);
  EXPECT_EQ(analysis.safe(), false);
  ASSERT_TRUE(analysis.dead_transitions);
  EXPECT_TRUE(analysis.dead_transitions->empty());
  EXPECT_EQ(analysis.deadlock, true);
  EXPECT_EQ(ids(net, analysis.deadlock_trace), (std::vector<std::string>{"stop"}));
  EXPECT_EQ(analysis.reversible, false);
}

// A net from text, read as any P/T net.
Net netOf(const std::string& body) {
  PnmlReadOptions options;
  options.schedule = false;
  return readPnmlString("<pnml><net id=\"n\">" + body + "</net></pnml>", "inline.pnml", options);
}

TEST(NetAnalysis, CoverabilityFindsADeadTransitionOfAnUnboundedNet) {
  // grow: a -> a + b for ever; never needs c, which no transition fills.
  const Net net = netOf(R"(<place id="a"><initialMarking><text>1</text></initialMarking></place>
      <place id="b"/><place id="c"/>
      <transition id="grow"/><transition id="never"/>
      <arc id="1" source="a" target="grow"/><arc id="2" source="grow" target="a"/>
      <arc id="3" source="grow" target="b"/><arc id="4" source="c" target="never"/>
      <arc id="5" source="never" target="b"/>)");
  const NetAnalysis analysis = analyseNet(net);
  EXPECT_EQ(analysis.bounded, false);
  ASSERT_TRUE(analysis.dead_transitions);
  EXPECT_EQ(ids(net, *analysis.dead_transitions), (std::vector<std::string>{"never"}));
  // No deadlock was found and the search cannot finish: unknown, not "none".
  EXPECT_EQ(analysis.deadlock, std::nullopt);
  EXPECT_EQ(analysis.reversible, std::nullopt);
}

TEST(NetAnalysis, CoverabilityGivesTheBoundsTheSearchCouldNotReach) {
  // Twelve independent toggles: 4096 markings, each place at most 1.
  std::string body;
  for (int i = 0; i < 12; ++i) {
    const std::string n = std::to_string(i);
    body += "<place id=\"off" + n + "\"><initialMarking><text>1</text></initialMarking></place><place id=\"on" + n +
            "\"/><transition id=\"up" + n + "\"/><transition id=\"down" + n + "\"/>" + "<arc id=\"a" + n +
            "\" source=\"off" + n + "\" target=\"up" + n + "\"/><arc id=\"b" + n + "\" source=\"up" + n +
            "\" target=\"on" + n + "\"/><arc id=\"c" + n + "\" source=\"on" + n + "\" target=\"down" + n +
            "\"/><arc id=\"d" + n + "\" source=\"down" + n + "\" target=\"off" + n + "\"/>";
  }
  const Net net = netOf(body);
  const NetAnalysis full = analyseNet(net);
  EXPECT_EQ(full.markings, 4096u);
  EXPECT_EQ(full.safe(), true);
  EXPECT_EQ(full.reversible, true);
  NetAnalysisOptions cut;
  cut.max_markings = 100;
  const NetAnalysis partial = analyseNet(net, cut);
  EXPECT_FALSE(partial.complete);
  EXPECT_EQ(partial.markings, 100u);
  // The coverability graph of a bounded net is its reachability graph: cut too.
  EXPECT_EQ(partial.bounded, std::nullopt);
  EXPECT_EQ(partial.safe(), std::nullopt);
  EXPECT_EQ(partial.dead_transitions, std::nullopt);
  EXPECT_EQ(partial.deadlock, std::nullopt);
  EXPECT_EQ(partial.reversible, std::nullopt);
}

TEST(NetAnalysis, RandomWalksFindADeadlockDeeperThanTheSearchWent) {
  // emit adds one to out for ever; stop needs 300 of them, then nothing is enabled.
  const Net net = netOf(R"(<place id="on"><initialMarking><text>1</text></initialMarking></place>
      <place id="out"/><place id="off"/><transition id="emit"/><transition id="stop"/>
      <arc id="1" source="on" target="emit"/><arc id="2" source="emit" target="on"/>
      <arc id="3" source="emit" target="out"/><arc id="4" source="on" target="stop"/>
      <arc id="5" source="out" target="stop"><inscription><text>300</text></inscription></arc>
      <arc id="6" source="stop" target="off"/>)");
  NetAnalysisOptions options;
  options.max_markings = 3000;
  const NetAnalysis analysis = analyseNet(net, options);
  EXPECT_LT(analysis.markings, 300u);  // the search stopped short of the deadlock
  ASSERT_EQ(analysis.deadlock, true);
  EXPECT_TRUE(analysis.deadlock_by_random_walk);
  ASSERT_GE(analysis.deadlock_trace.size(), 301u);
  EXPECT_EQ(net.transitions[analysis.deadlock_trace.back()].id, "stop");
  EXPECT_EQ(analysis.deadlock_marking[net.placeIndex("off")], 1);
  // Seeded: the same trace every time.
  EXPECT_EQ(analyseNet(net, options).deadlock_trace, analysis.deadlock_trace);
}

TEST(Coverability, RaisesToOmegaOnlyWhatGrows) {
  const Net net = anyNet("generator.pnml");
  const Coverability graph = coverabilityGraph(net, 1000);
  ASSERT_TRUE(graph.complete);
  EXPECT_FALSE(graph.max_tokens[net.placeIndex("out")].has_value());
  EXPECT_EQ(graph.max_tokens[net.placeIndex("on")], 1);
  EXPECT_EQ(graph.max_tokens[net.placeIndex("off")], 1);
  EXPECT_EQ(graph.can_fire, (std::vector<bool>{true, true}));
  // initial, its emit successor (out = omega), stop from each: 4 nodes.
  EXPECT_EQ(graph.nodes, 4u);
}

}  // namespace
}  // namespace beft::arbiter
