// Reachability analysis: state counts worked out by hand for the repository's
// nets, and the crafted nets that are not safe, have a dead transition, can
// deadlock or grow without bound.
#include <gtest/gtest.h>

#include <string>

#include "lib/petri/pnml_reader.hpp"
#include "lib/petri/reachability_graph.hpp"

namespace beft::arbiter {
namespace {

const std::string kNets = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/";
const std::string kTestNets = std::string(BEFT_TEST_NETS_DIR) + "/";

TEST(Reachability, DefaultNetIsSafeAndLive) {
  const Net net = readPnmlFile(kNets + "default.pnml");
  const auto report = exploreReachability(net);
  EXPECT_TRUE(report.complete);
  EXPECT_TRUE(report.safe);
  EXPECT_TRUE(report.dead_transitions.empty());
  EXPECT_EQ(report.num_deadlocks, 0u);
  EXPECT_EQ(report.num_states_without_tick_end, 0u);
  EXPECT_TRUE(report.ok());
  // By hand: tick start, world running, 3 low experts each waiting / running /
  // done (27), 2 mid experts likewise (9), then fusion running, dw waiting,
  // running, exploration waiting, running, tasks waiting, running, tick end.
  EXPECT_EQ(report.num_states, 1u + 1 + 27 + 9 + 1 + 2 + 2 + 2 + 1);
  // Seven of them have every place empty (something running everywhere):
  // world, all low, all mid, fusion, dw, exploration, tasks.
  EXPECT_EQ(report.num_place_markings, report.num_states - 6);
}

TEST(Reachability, OtherRepositoryNetsAreSafeAndLive) {
  const auto experts_only = exploreReachability(readPnmlFile(kNets + "experts_only.pnml"));
  EXPECT_TRUE(experts_only.ok());
  EXPECT_EQ(experts_only.num_states, 1u + 1 + 27 + 9 + 1 + 1);
  const auto sequential = exploreReachability(readPnmlFile(kNets + "sequential.pnml"));
  EXPECT_TRUE(sequential.ok());
  // Tick start, then for each of 10 experts: running, then its output place
  // (the last one's is the tick end).
  EXPECT_EQ(sequential.num_states, 1u + 10 * 2);
}

TEST(Reachability, FindsANetThatIsNotSafe) {
  const Net net = readPnmlFile(kTestNets + "unsafe.pnml");
  const auto report = exploreReachability(net);
  EXPECT_TRUE(report.complete);
  EXPECT_FALSE(report.unbounded);
  EXPECT_FALSE(report.safe);
  EXPECT_TRUE(report.live());  // the only fault is safety
  EXPECT_FALSE(report.ok());
  ASSERT_TRUE(report.unsafe_witness.has_value());
  EXPECT_EQ(net.places[report.unsafe_place].id, "p_objects");
  EXPECT_EQ(report.unsafe_witness->tokens[report.unsafe_place], 2);
  EXPECT_EQ(report.unsafe_witness->trace, (std::vector<std::string>{"start t_world", "end t_world"}));
}

TEST(Reachability, FindsADeadTransition) {
  const Net net = readPnmlFile(kTestNets + "dead_transition.pnml");
  const auto report = exploreReachability(net);
  EXPECT_TRUE(report.safe);
  EXPECT_EQ(report.num_states_without_tick_end, 0u);
  ASSERT_EQ(report.dead_transitions.size(), 1u);
  EXPECT_EQ(net.transitions[report.dead_transitions[0]].id, "t_audio");
  EXPECT_FALSE(report.live());
}

TEST(Reachability, FindsADeadlock) {
  const Net net = readPnmlFile(kTestNets + "deadlock.pnml");
  const auto report = exploreReachability(net);
  EXPECT_TRUE(report.safe);
  EXPECT_TRUE(report.dead_transitions.empty());
  EXPECT_EQ(report.num_deadlocks, 1u);
  ASSERT_EQ(report.deadlock_witnesses.size(), 1u);
  EXPECT_EQ(describeState(net, report.deadlock_witnesses[0]), "p_stuck=1");
  EXPECT_EQ(report.deadlock_witnesses[0].trace,
            (std::vector<std::string>{"start t_world", "end t_world", "start t_audio", "end t_audio"}));
  // Audio running and its dead end: neither can reach the tick end.
  EXPECT_EQ(report.num_states_without_tick_end, 2u);
  EXPECT_FALSE(report.live());
}

TEST(Reachability, ProvesANetUnbounded) {
  const Net net = readPnmlFile(kTestNets + "unbounded.pnml");
  const auto report = exploreReachability(net);
  EXPECT_TRUE(report.unbounded);
  EXPECT_FALSE(report.complete);
  EXPECT_FALSE(report.ok());
  ASSERT_TRUE(report.unbounded_witness.has_value());
  EXPECT_GE(report.growing_place, 0);
}

TEST(Reachability, StopsAtTheStateBound) {
  const auto report = exploreReachability(readPnmlFile(kNets + "default.pnml"), ReachabilityOptions{10});
  EXPECT_FALSE(report.complete);
  EXPECT_FALSE(report.unbounded);
  EXPECT_FALSE(report.live());
  EXPECT_EQ(report.num_states_without_tick_end, 0u);  // not judged on a partial graph
}

// Two transitions enabled together: with two experts they may run at once
// (3 x 3 states between fork and join), with one expert never both.
TEST(Reachability, AnExpertRunsOneFiringAtATime) {
  const auto net_with = [](const std::string& expert_a, const std::string& expert_b) {
    return readPnmlString(
        "<pnml><net id=\"n\">"
        "<place id=\"p0\"><initialMarking><text>1</text></initialMarking></place>"
        "<place id=\"pa\"/><place id=\"pb\"/><place id=\"qa\"/><place id=\"qb\"/>"
        "<transition id=\"fork\"><toolspecific tool=\"beft\"><silent/></toolspecific></transition>"
        "<transition id=\"ta\"><toolspecific tool=\"beft\"><expert>" + expert_a + "</expert></toolspecific></transition>"
        "<transition id=\"tb\"><toolspecific tool=\"beft\"><expert>" + expert_b + "</expert></toolspecific></transition>"
        "<transition id=\"tick\"><toolspecific tool=\"beft\"><tick/></toolspecific></transition>"
        "<arc id=\"a1\" source=\"p0\" target=\"fork\"/><arc id=\"a2\" source=\"fork\" target=\"pa\"/>"
        "<arc id=\"a3\" source=\"fork\" target=\"pb\"/><arc id=\"a4\" source=\"pa\" target=\"ta\"/>"
        "<arc id=\"a5\" source=\"pb\" target=\"tb\"/><arc id=\"a6\" source=\"ta\" target=\"qa\"/>"
        "<arc id=\"a7\" source=\"tb\" target=\"qb\"/><arc id=\"a8\" source=\"qa\" target=\"tick\"/>"
        "<arc id=\"a9\" source=\"qb\" target=\"tick\"/><arc id=\"a10\" source=\"tick\" target=\"p0\"/>"
        "</net></pnml>",
        "fork.pnml");
  };
  const auto two_experts = exploreReachability(net_with("vision", "audio"));
  const auto one_expert = exploreReachability(net_with("vision", "vision"));
  EXPECT_EQ(two_experts.num_states, 1u + 9);
  EXPECT_EQ(one_expert.num_states, 1u + 9 - 1);  // never both running
  EXPECT_TRUE(two_experts.ok());
  EXPECT_TRUE(one_expert.ok());
}

}  // namespace
}  // namespace beft::arbiter
