// Drawing a net: the graph holds the places with their tokens, the
// transitions with their experts, and a run's last marking.
#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>

#include <beft/marking_t.hpp>

#include <string>

#include "lib/petri/net_dot.hpp"
#include "lib/petri/pnml_reader.hpp"
#include "lib/wire/run_identity.hpp"
#include "tools/net_draw/run_marking.hpp"
#include "tests/system/run_support.hpp"

namespace {

using namespace beft;

const std::string kDefaultNet = system_test::sourceDir() + "/scenarios/nets/default.pnml";

TEST(NetDot, ShowsTokensExpertsAndTheTick) {
  const arbiter::Net net = arbiter::readPnmlFile(kDefaultNet);
  const std::string dot = arbiter::netToDot(net, std::nullopt);
  const int start = net.placeIndex("p_tick_start");
  ASSERT_GE(start, 0);
  EXPECT_NE(dot.find("p" + std::to_string(start) + " [shape=circle, width=0.45, fixedsize=true, label=\"\u25CF\""),
            std::string::npos)
      << dot;
  EXPECT_NE(dot.find("world step (t_world)\\nworld"), std::string::npos);
  EXPECT_NE(dot.find("\\ntick\", peripheries=2"), std::string::npos);
  size_t arcs = 0;
  for (size_t at = dot.find(" -> "); at != std::string::npos; at = dot.find(" -> ", at + 1)) ++arcs;
  EXPECT_EQ(arcs, net.arcCount());
}

// The viewer lights a drawn net by these names: one per place and transition.
TEST(NetDot, NamesEveryNodeForAPageToFind) {
  const arbiter::Net net = arbiter::readPnmlFile(kDefaultNet);
  const std::string dot = arbiter::netToDot(net, std::nullopt);
  for (const auto& place : net.places)
    EXPECT_NE(dot.find("id=\"place:" + place.id + "\", class=\"place\""), std::string::npos) << place.id;
  for (const auto& transition : net.transitions) {
    const std::string classes = transition.expert.empty() ? "transition" : "transition expert-" + transition.expert;
    EXPECT_NE(dot.find("id=\"transition:" + transition.id + "\", class=\"" + classes + "\""), std::string::npos)
        << transition.id;
  }
}

// A log with two runs' markings; the drawing takes the newest of the one asked for.
std::string writeMarkingLog(int64_t run_a, int64_t run_b) {
  const std::string path = system_test::makeTempDir("net_draw") + "/run.lcmlog";
  lcm::LogFile log(path, "w");
  const auto add = [&](int64_t run, int64_t tick, const std::string& place, int tokens, const std::string& running) {
    beft::marking_t marking{};
    marking.tick = tick;
    marking.step = tick * 10;
    marking.event = "done tasks";
    marking.num_places = 2;
    marking.place_ids = {"p_tick_start", place};
    marking.tokens = {0, tokens};
    marking.num_running = running.empty() ? 0 : 1;
    if (!running.empty()) marking.running = {running};
    std::vector<uint8_t> bytes(marking.getEncodedSize());
    marking.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    lcm::LogEvent event{};
    event.timestamp = tick;
    const std::string channel = "MARKING@" + wire::runIdText(run);
    event.channel = channel;
    event.datalen = static_cast<int32_t>(bytes.size());
    event.data = bytes.data();
    log.writeEvent(&event);
  };
  add(run_a, 1, "p_vision_in", 1, "vision");
  add(run_b, 2, "p_audio_in", 1, "");
  add(run_a, 3, "p_tasks_in", 1, "tasks");
  add(run_b, 4, "p_dw_in", 1, "");
  return path;
}

TEST(RunMarking, TheNewestMarkingOfTheRunAskedFor) {
  const std::string path = writeMarkingLog(0x1a, 0x2b);
  const auto a = net_draw::lastMarkingOfRun(path);  // the log's first run
  ASSERT_TRUE(a);
  EXPECT_EQ(a->tokens.at("p_tasks_in"), 1);
  EXPECT_EQ(a->running, (std::vector<std::string>{"tasks"}));
  EXPECT_NE(a->caption.find("tick 3"), std::string::npos) << a->caption;
  const auto b = net_draw::lastMarkingOfRun(path, wire::runIdText(0x2b));
  ASSERT_TRUE(b);
  EXPECT_EQ(b->tokens.at("p_dw_in"), 1);
  EXPECT_TRUE(b->running.empty());

  const arbiter::Net net = arbiter::readPnmlFile(kDefaultNet);
  const std::string dot = arbiter::netToDot(net, a);
  const int tasks = net.placeIndex("p_tasks_in");
  const int start = net.placeIndex("p_tick_start");
  EXPECT_NE(dot.find("p" + std::to_string(tasks) + " [shape=circle, width=0.45, fixedsize=true, label=\"\u25CF\""),
            std::string::npos);
  EXPECT_NE(dot.find("p" + std::to_string(start) + " [shape=circle, width=0.45, fixedsize=true, label=\"\""),
            std::string::npos);
  EXPECT_NE(dot.find("task executor (t_tasks)\\ntasks\", style=filled"), std::string::npos) << dot;
}

TEST(NetDrawProcess, WritesADotFileAndRefusesAnUnknownFormat) {
  const std::string dir = system_test::makeTempDir("net_draw_process");
  const auto run = system_test::runCommand(system_test::binDir() + "/beft-net-draw " + kDefaultNet + " --out " + dir +
                                               "/net.dot --log " + writeMarkingLog(0x1a, 0x2b),
                                           60);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("tick 3"), std::string::npos) << run.output;
  const auto dot = system_test::runCommand("cat " + dir + "/net.dot", 10).output;
  EXPECT_EQ(dot.rfind("digraph \"beft_default\" {", 0), 0u) << dot.substr(0, 80);
  const auto bad = system_test::runCommand(system_test::binDir() + "/beft-net-draw " + kDefaultNet + " --out " + dir +
                                               "/net.jpeg", 60);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("--out must end in .svg, .png, .pdf or .dot"), std::string::npos) << bad.output;
}

}  // namespace
