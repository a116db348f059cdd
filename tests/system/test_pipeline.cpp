// The expert hierarchy as separate processes (a short run of yard.xml):
// schedule order from the log, labels against the model library, replay of
// experts against the recorded log, lcm-logplayer, and running one expert by hand.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/geometry_percepts_t.hpp>
#include <beft/labels_t.hpp>
#include <beft/plan_request_t.hpp>
#include <beft/run_status_t.hpp>
#include <beft/acoustic_percepts_t.hpp>
#include <beft/camera_frame_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/visual_percepts_t.hpp>

#include "lib/camera/frame_decoding.hpp"
#include "lib/model/model.hpp"
#include "lib/wire/encoded_stamp.hpp"
#include "lib/wire/run_identity.hpp"
#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

constexpr int kShortTicks = 40;

struct ShortRun {
  std::string dir;
  ProgramResult result;
  std::vector<LoggedMessage> log;
};

// Whether every FIRE and DONE of the middle ticks reached the log.
bool logHasEveryFiring(const std::vector<LoggedMessage>& log) {
  std::set<std::pair<int64_t, std::string>> fires, dones;
  for (const auto& event : log) {
    if (event.channel == "FIRE") {
      beft::fire_t f{};
      if (f.decode(event.data.data(), 0, static_cast<int>(event.data.size())) > 0) fires.insert({f.tick, f.expert});
    } else if (event.channel == "DONE") {
      beft::done_t d{};
      if (d.decode(event.data.data(), 0, static_cast<int>(event.data.size())) > 0) dones.insert({d.tick, d.expert});
    }
  }
  for (int64_t tick = 1; tick < kShortTicks - 1; ++tick)
    for (const auto& e : {"world", "geometry", "vision", "audio", "visual_labels", "acoustic_labels", "fusion",
                          "dw", "exploration", "tasks"})
      if (!fires.count({tick, e}) || !dones.count({tick, e})) return false;
  // And one message per tick on the channels the replayed experts read and write.
  std::map<std::string, std::set<int64_t>> ticks_of;
  for (const auto& g : messagesOn<beft::geometry_percepts_t>(log, "GEOMETRY")) ticks_of["GEOMETRY"].insert(g.tick);
  for (const auto& v : messagesOn<beft::visual_percepts_t>(log, "VISION")) ticks_of["VISION"].insert(v.tick);
  for (const auto& a : messagesOn<beft::acoustic_percepts_t>(log, "AUDIO")) ticks_of["AUDIO"].insert(a.tick);
  for (const auto& o : messagesOn<beft::scene_objects_t>(log, "GT_OBJECTS")) ticks_of["GT_OBJECTS"].insert(o.tick);
  for (const auto& l : messagesOn<beft::labels_t>(log, "LABELS_VISUAL")) ticks_of["LABELS_VISUAL"].insert(l.tick);
  for (const auto& l : messagesOn<beft::labels_t>(log, "LABELS_ACOUSTIC")) ticks_of["LABELS_ACOUSTIC"].insert(l.tick);
  for (const auto& h : hypothesesOfEachTick(log)) ticks_of["HYPOTHESES"].insert(h.tick);
  for (const auto& [channel, ticks] : ticks_of)
    for (int64_t tick = 0; tick < kShortTicks; ++tick)
      if (!ticks.count(tick)) return false;
  return ticks_of.size() == 7;
}

// The logger hears the run over UDP like any other process; on a busy
// machine it may lose a datagram, and a replay compares against what it
// recorded. So the run is recorded again (at most twice more) when its log
// visibly lost a message.
const ShortRun& shortYardRun() {
  static ShortRun run = [] {
    ShortRun r;
    for (int attempt = 0; attempt < 3; ++attempt) {
      r.dir = makeTempDir("short_yard");
      r.result = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --max-ticks " +
                                std::to_string(kShortTicks) + " --no-report --out " + r.dir,
                            300);
      try {
        r.log = readLog(r.dir + "/run.lcmlog");
      } catch (const std::exception& e) {
        r.result.output += e.what();
      }
      if (r.result.exit_code != 0 || logHasEveryFiring(r.log)) break;
      std::printf("[test] the log of %s lost a message; recording again\n", r.dir.c_str());
    }
    return r;
  }();
  return run;
}

const std::vector<std::string> kLow = {"geometry", "vision", "audio"};
const std::vector<std::string> kMid = {"visual_labels", "acoustic_labels"};
const std::vector<std::string> kHigh = {"fusion", "dw", "exploration", "tasks"};

}  // namespace

TEST(Pipeline, EachExpertFiresOncePerTickInThePapersOrder) {
  const auto& run = shortYardRun();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  // Position in the log of the first FIRE and the first DONE of each (tick, expert).
  std::map<std::pair<int64_t, std::string>, std::size_t> first_fire, first_done;
  std::map<std::pair<int64_t, std::string>, std::set<int64_t>> firing_ids;
  for (std::size_t i = 0; i < run.log.size(); ++i) {
    const auto& event = run.log[i];
    if (event.channel == "FIRE") {
      beft::fire_t f{};
      f.decode(event.data.data(), 0, static_cast<int>(event.data.size()));
      first_fire.emplace(std::make_pair(f.tick, f.expert), i);
      firing_ids[{f.tick, f.expert}].insert(f.firing_id);
    } else if (event.channel == "DONE") {
      beft::done_t d{};
      d.decode(event.data.data(), 0, static_cast<int>(event.data.size()));
      first_done.emplace(std::make_pair(d.tick, d.expert), i);
    }
  }
  // The logger hears the run over UDP and may lose a datagram on a busy machine:
  // order is checked on every tick whose FIRE and DONE all reached the log.
  int ticks_checked = 0, ticks_incomplete = 0;
  for (int64_t tick = 1; tick < kShortTicks - 1; ++tick) {
    auto fire = [&](const std::string& e) { return first_fire.at({tick, e}); };
    auto done = [&](const std::string& e) { return first_done.at({tick, e}); };
    std::vector<std::string> all = {"world"};
    all.insert(all.end(), kLow.begin(), kLow.end());
    all.insert(all.end(), kMid.begin(), kMid.end());
    all.insert(all.end(), kHigh.begin(), kHigh.end());
    bool complete = true;
    for (const auto& e : all) complete &= first_fire.count({tick, e}) && first_done.count({tick, e});
    if (!complete) {
      ++ticks_incomplete;
      continue;
    }
    for (const auto& e : all)
      EXPECT_EQ(firing_ids[std::make_pair(tick, e)].size(), 1u) << e << " fired twice in tick " << tick;
    for (const auto& low : kLow) EXPECT_LT(done("world"), fire(low)) << tick;
    for (const auto& mid : kMid)
      for (const auto& low : kLow) EXPECT_LT(done(low), fire(mid)) << tick << " " << low << " " << mid;
    for (const auto& mid : kMid) EXPECT_LT(done(mid), fire("fusion")) << tick;
    for (std::size_t i = 1; i < kHigh.size(); ++i) EXPECT_LT(done(kHigh[i - 1]), fire(kHigh[i])) << tick;
    ++ticks_checked;
  }
  EXPECT_GE(ticks_checked, (kShortTicks - 2) * 3 / 4) << ticks_incomplete << " ticks lost a message in the log";

  // Exactly once per tick, from the arbiter's own record of every firing
  // ("[arbiter] tick K firing ID EXPERT ok ..." in processes.log).
  const std::string record = runCommand("cat " + run.dir + "/processes.log", 10).output;
  std::map<std::pair<int64_t, std::string>, int> firings;
  std::istringstream lines(record);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string prefix, tick_word, firing_word, expert, outcome;
    long long tick = -1, id = -1;
    if (!(words >> prefix >> tick_word >> tick >> firing_word >> id >> expert >> outcome)) continue;
    if (prefix != "[arbiter]" || tick_word != "tick" || firing_word != "firing") continue;
    EXPECT_EQ(outcome, "ok") << line;
    ++firings[{tick, expert}];
  }
  for (int64_t tick = 0; tick < kShortTicks; ++tick)
    for (const auto& e : {"world", "geometry", "vision", "audio", "visual_labels", "acoustic_labels", "fusion",
                          "dw", "exploration", "tasks"})
      EXPECT_EQ((firings[{tick, e}]), 1) << e << " in tick " << tick;
}

TEST(Pipeline, EveryProcessReceivesOnlyWhatItReads) {
  // On udpm every process reads a socket of its own with a kernel filter: an
  // expert's inputs on one (read when a FIRE comes), its own firings and the
  // run's end on the one it waits on.
  const ShortRun& run = shortYardRun();
  const std::string record = runCommand("cat " + run.dir + "/processes.log", 10).output;
  auto lineAfter = [&record](const std::string& start) {
    const auto at = record.find(start);
    return at == std::string::npos ? std::string() : record.substr(at, record.find('\n', at) - at);
  };
  for (const std::string process : {"world", "geometry", "vision", "audio", "visual_labels", "acoustic_labels",
                                    "fusion", "dw", "exploration", "tasks"}) {
    const std::string prefix = "[" + process + "] [" + process + "] info: ";
    const std::string inputs = lineAfter(prefix + "inputs: own receive socket");
    const std::string control = lineAfter(prefix + "control: own receive socket");
    EXPECT_NE(inputs.find("kernel filter: receiving only "), std::string::npos) << process << ":\n" << inputs;
    EXPECT_EQ(inputs.find("FIRE"), std::string::npos) << inputs;
    EXPECT_NE(control.find("kernel filter: receiving only FIRE (own firings), RUN_STATUS (waiting and end of run)"),
              std::string::npos)
        << process << ":\n" << control;
  }
  EXPECT_NE(lineAfter("[vision] [vision] info: inputs: ").find("CAMERA_DEPTH, CAMERA_INSTANCE, CONTACT, GT_OBJECTS"),
            std::string::npos);
  EXPECT_NE(lineAfter("[arbiter] [arbiter] info: receiving: own receive socket")
                .find("kernel filter: receiving only DONE, HEARTBEAT, STOP_REQUEST"),
            std::string::npos)
      << record.substr(0, 3000);
  EXPECT_NE(lineAfter("[planner] [planner] info: requests: own receive socket").find("receiving only PLAN_REQUEST"),
            std::string::npos);
  EXPECT_NE(lineAfter("[planner] [planner] info: maps: own receive socket").find("receiving only OBSTACLE_MAP"),
            std::string::npos);
  EXPECT_NE(lineAfter("[blackboard] [blackboard] info: stored: own receive socket")
                .find("kernel filter: dropping FIRE, DONE, HEARTBEAT, MARKING, BB_QUERY"),
            std::string::npos);
  EXPECT_NE(lineAfter("[blackboard] [blackboard] info: queries: own receive socket")
                .find("kernel filter: receiving only BB_QUERY"),
            std::string::npos);
}

TEST(Pipeline, LabelsOnTheBlackboardMatchTheModelLibrary) {
  const auto& run = shortYardRun();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  std::map<int64_t, beft::geometry_percepts_t> geometry;
  std::map<int64_t, beft::visual_percepts_t> vision;
  std::map<int64_t, beft::acoustic_percepts_t> audio;
  std::map<std::string, std::string> label_of, acoustic_label_of;
  for (const auto& g : messagesOn<beft::geometry_percepts_t>(run.log, "GEOMETRY")) geometry[g.tick] = g;
  for (const auto& v : messagesOn<beft::visual_percepts_t>(run.log, "VISION")) vision[v.tick] = v;
  for (const auto& a : messagesOn<beft::acoustic_percepts_t>(run.log, "AUDIO")) audio[a.tick] = a;
  for (const auto& gt : messagesOn<beft::scene_objects_t>(run.log, "GT_OBJECTS"))
    for (const auto& o : gt.objects) label_of[o.id] = o.label, acoustic_label_of[o.id] = o.acoustic_label;
  int visual_checked = 0, acoustic_checked = 0;
  for (const auto& labels : messagesOn<beft::labels_t>(run.log, "LABELS_VISUAL")) {
    if (!geometry.count(labels.tick) || !vision.count(labels.tick)) continue;
    for (const auto& object : labels.objects) {
      double d = -1, occlusion = -1;
      for (const auto& p : geometry[labels.tick].percepts) if (p.object_id == object.object_id) d = p.distance;
      for (const auto& p : vision[labels.tick].percepts) if (p.object_id == object.object_id) occlusion = p.occlusion;
      ASSERT_GE(d, 0);
      ASSERT_GE(occlusion, 0);
      const double v_p = beft::model::visualPerceptibility(d, occlusion);  // eq. 1
      EXPECT_NEAR(object.perceptibility, v_p, 1e-9) << object.object_id;
      for (int j = 0; j < object.num_categories; ++j)
        EXPECT_NEAR(object.confidence[j],
                    beft::model::labelConfidence(object.categories[j] == label_of[object.object_id], v_p), 1e-9);
      ++visual_checked;
    }
  }
  for (const auto& labels : messagesOn<beft::labels_t>(run.log, "LABELS_ACOUSTIC")) {
    if (!geometry.count(labels.tick) || !audio.count(labels.tick)) continue;
    for (const auto& object : labels.objects) {
      double d = -1, alpha = 0, occlusion = -1;
      for (const auto& p : geometry[labels.tick].percepts)
        if (p.object_id == object.object_id) d = p.distance, alpha = p.azimuth;
      for (const auto& p : audio[labels.tick].percepts) if (p.object_id == object.object_id) occlusion = p.occlusion;
      ASSERT_GE(d, 0);
      ASSERT_GE(occlusion, 0);
      const double a_p = beft::model::acousticPerceptibility(d, occlusion, alpha);  // eq. 2
      EXPECT_NEAR(object.perceptibility, a_p, 1e-9) << object.object_id;
      for (int j = 0; j < object.num_categories; ++j)
        EXPECT_NEAR(object.confidence[j],
                    beft::model::labelConfidence(object.categories[j] == acoustic_label_of[object.object_id], a_p),
                    1e-9);
      ++acoustic_checked;
    }
  }
  EXPECT_GT(visual_checked, kShortTicks);
  EXPECT_GT(acoustic_checked, kShortTicks);
}

TEST(Replay, FusionAndVisualLabelsMatchTheRecordedRunExactly) {
  const auto& run = shortYardRun();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  for (const char* module : {"fusion", "visual_labels"}) {
    const auto replay = runCommand(binDir() + "/beft-replay " + run.dir + "/run.lcmlog --module " + module, 120);
    EXPECT_EQ(replay.exit_code, 0) << replay.output;
    EXPECT_NE(replay.output.find("EXACT MATCH"), std::string::npos) << replay.output;
  }
}

TEST(Replay, VisionMatchesTheRecordedRunExactlyFromItsCompressedFrames) {
  const auto& run = shortYardRun();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  int compressed = 0;
  for (const char* channel : {"CAMERA_DEPTH", "CAMERA_INSTANCE"})
    for (const auto& frame : messagesOn<beft::camera_frame_t>(run.log, channel))
      compressed += frame.compression != beft::camera_frame_t::COMPRESSION_NONE;
  EXPECT_GE(compressed, 2 * (kShortTicks - 1)) << "the frames the replay reads were not compressed";
  const auto replay = runCommand(binDir() + "/beft-replay " + run.dir + "/run.lcmlog --module vision", 120);
  EXPECT_EQ(replay.exit_code, 0) << replay.output;
  EXPECT_NE(replay.output.find("EXACT MATCH"), std::string::npos) << replay.output;
  EXPECT_NE(replay.output.find(std::to_string(kShortTicks) + " firings"), std::string::npos) << replay.output;
}

TEST(Replay, AChangedParameterShowsTheDifference) {
  const auto& run = shortYardRun();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto replay = runCommand(
      binDir() + "/beft-replay " + run.dir + "/run.lcmlog --module visual_labels --param label_gain=10", 120);
  EXPECT_EQ(replay.exit_code, 3) << replay.output;
  EXPECT_NE(replay.output.find("DIFFERENCES FOUND"), std::string::npos) << replay.output;
  EXPECT_NE(replay.output.find("first difference on LABELS_VISUAL"), std::string::npos) << replay.output;
  EXPECT_NE(replay.output.find("confidence"), std::string::npos) << replay.output;
}

TEST(Replay, LcmLogplayerPlaysTheLogIntoASubscriberThatHearsEveryChannel) {
  const auto& run = shortYardRun();
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  std::set<std::string> logged;
  for (const auto& event : run.log) logged.insert(event.channel);
  const int port = 23000 + getpid() % 5000;
  const std::string url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0&recv_buf_size=8388608";
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  std::set<std::string> heard;
  struct Handler {
    std::set<std::string>* heard;
    void on(const lcm::ReceiveBuffer*, const std::string& channel) { heard->insert(channel); }
  } handler{&heard};
  lcm.subscribe(".*", &Handler::on, &handler)->setQueueCapacity(100000);
  const pid_t player = fork();
  if (player == 0) {
    execlp("lcm-logplayer", "lcm-logplayer", "--speed=2", ("--lcm-url=" + url).c_str(),
           (run.dir + "/run.lcmlog").c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (heard.size() < logged.size() && std::chrono::steady_clock::now() < deadline) lcm.handleTimeout(50);
  kill(player, SIGTERM);
  waitpid(player, nullptr, 0);
  // The log holds the run's channels as heard ("VISION@<run>"); readLog gives their plain names.
  std::set<std::string> heard_plain;
  for (const auto& channel : heard) heard_plain.insert(std::string(beft::wire::splitRunChannel(channel).base));
  EXPECT_EQ(heard_plain, logged);
  EXPECT_GE(logged.size(), 15u);
}

namespace {
// A run of yard.xml in the background without the process `left_out`, its
// output in dir/run_output.txt: its pid, and the URL and run id a process
// started by hand needs (read from what beft-run prints).
struct RunWithoutOne {
  pid_t pid = -1;
  std::string url, run_id;
};
RunWithoutOne startRunWithout(const std::string& left_out, int ticks, const std::string& dir) {
  RunWithoutOne run;
  run.pid = fork();
  if (run.pid == 0) {
    const std::string command = binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --max-ticks " +
                                std::to_string(ticks) + " --no-report --except " + left_out + " --out " + dir + " > " +
                                dir + "/run_output.txt 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 600 && (run.url.empty() || run.run_id.empty()); ++i) {  // at most a minute
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const auto out = runCommand("cat " + dir + "/run_output.txt", 5).output;
    const auto line = lineAfter(out, "[run] LCM ");
    if (!line.empty()) run.url = line.substr(0, line.find(';'));
    const auto env = lineAfter(out, "    BEFT_RUN_ID=");
    if (!env.empty()) run.run_id = env.substr(0, env.find(' '));
  }
  return run;
}

// Listens to the run's RUN_STATUS until its arbiter says it waits for the
// first heartbeat of `process` alone: every other process is up, and the run
// goes no further until `process` starts. False if not heard within a minute
// (the arbiter gives up on a missing process after 30 s).
bool runWaitsOnlyFor(const RunWithoutOne& run, const std::string& process) {
  lcm::LCM lcm(run.url);
  if (!lcm.good()) return false;
  struct Listener {
    std::string wanted;
    bool heard = false;
    void on(const lcm::ReceiveBuffer*, const std::string&, const beft::run_status_t* status) {
      heard = heard || (status->state == beft::run_status_t::STATE_WAITING && status->message == wanted);
    }
  } listener{"waiting for heartbeats from: " + process};
  lcm.subscribe(beft::wire::runChannel("RUN_STATUS", beft::wire::parseRunId(run.run_id)), &Listener::on, &listener);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!listener.heard && std::chrono::steady_clock::now() < deadline) lcm.handleTimeout(100);
  return listener.heard;
}
}  // namespace

TEST(Launch, AnExpertStartedByHandLaterCompletesTheRun) {
  const std::string dir = makeTempDir("except_vision");
  // The run starts without vision; the test starts it by hand once the run
  // waits for it alone.
  const RunWithoutOne run = startRunWithout("vision", 20, dir);
  const pid_t runner = run.pid;
  // The launcher prints the command line that joins the run (its URL and run id).
  const std::string command_line =
      "BEFT_RUN_ID=" + lineAfter(runCommand("cat " + dir + "/run_output.txt", 5).output, "    BEFT_RUN_ID=");
  ASSERT_NE(command_line.find("beft-vision --lcm-url"), std::string::npos) << command_line;
  ASSERT_TRUE(runWaitsOnlyFor(run, "vision")) << "the run never waited for vision alone";
  const auto vision = runCommand(command_line, 120);
  int status = 0;
  waitpid(runner, &status, 0);
  const auto out = runCommand("cat " + dir + "/run_output.txt", 5).output;
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out << "\nvision:\n" << vision.output;
  EXPECT_NE(out.find("not starting vision (--except)"), std::string::npos) << out;
  int vision_done = 0;
  for (const auto& d : messagesOn<beft::done_t>(readLog(dir + "/run.lcmlog"), "DONE")) vision_done += d.expert == "vision";
  EXPECT_GE(vision_done, 15);  // 20 ticks; the logger may lose a datagram
}

// The planner is a service the experts ask within a tick: a run that started
// before it was up lost the first plan request (yard.xml asks at tick 49),
// the executor waited 2 s for an answer that never came, and the mission
// went differently. The arbiter waits for its heartbeat too (mission.xml:
// --wait-for planner), so a planner started late changes nothing.
TEST(Launch, APlannerStartedLateChangesNothing) {
  constexpr int kTicks = 60;
  const std::string reference_dir = makeTempDir("planner_reference");
  const auto reference = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --max-ticks " +
                                        std::to_string(kTicks) + " --no-report --out " + reference_dir,
                                    300);
  ASSERT_EQ(reference.exit_code, 0) << reference.output;

  const std::string dir = makeTempDir("planner_late");
  const RunWithoutOne run = startRunWithout("planner", kTicks, dir);
  const pid_t runner = run.pid;
  const std::string &url = run.url, &run_id = run.run_id;
  ASSERT_FALSE(url.empty());
  ASSERT_FALSE(run_id.empty());
  // Late: every other process is up and the run is held for the planner alone.
  ASSERT_TRUE(runWaitsOnlyFor(run, "planner")) << "the run never waited for the planner alone";
  const pid_t planner = fork();
  if (planner == 0) {
    // mission.xml's arguments for the planner
    const std::string command = "env BEFT_RUN_ID=" + run_id + " " + binDir() +
                                "/beft-planner --planner pf-geodesic --robot-radius 0.5 --lcm-url '" +
                                url + "' > " + dir + "/planner_output.txt 2>&1";
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(runner, &status, 0);
  kill(planner, SIGTERM);
  waitpid(planner, nullptr, 0);
  const auto out = runCommand("cat " + dir + "/run_output.txt", 5).output;
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
  const auto late = readLog(dir + "/run.lcmlog");
  EXPECT_FALSE(messagesOn<beft::plan_request_t>(late, "PLAN_REQUEST").empty()) << "no plan asked within the run";
  const DataComparison comparison = compareDataMessages(readLog(reference_dir + "/run.lcmlog"), late);
  EXPECT_GT(comparison.expected, 0u);
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
}

// The blackboard too: started after the run's first tick, it would never
// hold the ground truth (sent only when the scene changes), and a process
// joining late or restarted would get none from it. The arbiter waits for
// its heartbeat (mission.xml: --wait-for blackboard).
TEST(Launch, ABlackboardStartedLateStillHoldsTheScene) {
  const std::string dir = makeTempDir("blackboard_late");
  const RunWithoutOne run = startRunWithout("blackboard", 30, dir);
  const pid_t runner = run.pid;
  const std::string &url = run.url, &run_id = run.run_id;
  ASSERT_FALSE(url.empty());
  ASSERT_FALSE(run_id.empty());
  // Late: every other process is up and the run is held for the blackboard alone.
  ASSERT_TRUE(runWaitsOnlyFor(run, "blackboard")) << "the run never waited for the blackboard alone";
  const pid_t blackboard = fork();
  if (blackboard == 0) {
    const std::string command = "env BEFT_RUN_ID=" + run_id + " " + binDir() + "/beft-blackboard --lcm-url '" + url +
                                "' > " + dir + "/blackboard_output.txt 2>&1";
    execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(runner, &status, 0);
  const auto out = runCommand("cat " + dir + "/run_output.txt", 5).output;
  // What the blackboard holds once the run is over.
  const auto dump = runCommand("env BEFT_RUN_ID=" + run_id + " " + binDir() + "/beft-blackboard-dump --lcm-url '" +
                                   url + "' --channel GT_OBJECTS --summary --timeout 5",
                               30);
  kill(blackboard, SIGTERM);
  waitpid(blackboard, nullptr, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
  const std::string processes = runCommand("cat " + dir + "/processes.log", 5).output;
  EXPECT_NE(processes.find("[arbiter] [arbiter] info: heard blackboard"), std::string::npos) << processes;
  EXPECT_EQ(dump.exit_code, 0) << dump.output;
  EXPECT_NE(dump.output.find("GT_OBJECTS"), std::string::npos) << "the blackboard never heard the scene:\n"
                                                                << dump.output;
}

// A short run of peek.xml recorded when the message types were first fixed:
// old logs must stay readable (types change by adding new ones; the one
// edited since, camera_frame_t, is read from its earlier layout by the log
// reader) and replay exactly.
TEST(OldLogs, ACommittedLogStillDecodesAndReplaysExactly) {
  const std::string log_path = sourceDir() + "/tests/system/data/peek_6_ticks.lcmlog";
  const auto log = readLog(log_path);
  ASSERT_GT(log.size(), 100u);
  std::map<std::string, int> decoded;
  auto check = [&](const auto& sample, const std::string& channel) {
    using Message = std::decay_t<decltype(sample)>;
    const auto messages = messagesOn<Message>(log, channel);
    int on_channel = 0;
    for (const auto& e : log) on_channel += e.channel == channel;
    EXPECT_EQ(static_cast<int>(messages.size()), on_channel) << channel << " no longer decodes";
    decoded[channel] = on_channel;
  };
  check(beft::fire_t{}, "FIRE");
  check(beft::done_t{}, "DONE");
  check(beft::scene_objects_t{}, "GT_OBJECTS");
  check(beft::geometry_percepts_t{}, "GEOMETRY");
  check(beft::visual_percepts_t{}, "VISION");
  check(beft::acoustic_percepts_t{}, "AUDIO");
  check(beft::labels_t{}, "LABELS_VISUAL");
  check(beft::labels_t{}, "LABELS_ACOUSTIC");
  // Recorded before camera_frame_t gained `compression`: read in today's layout, raw.
  for (const char* channel : {"CAMERA_COLOR", "CAMERA_DEPTH", "CAMERA_INSTANCE"}) {
    check(beft::camera_frame_t{}, channel);
    for (auto frame : messagesOn<beft::camera_frame_t>(log, channel)) {
      std::string why;
      EXPECT_EQ(frame.compression, beft::camera_frame_t::COMPRESSION_NONE);
      EXPECT_TRUE(beft::camera::decodeCameraFrame(frame, &why)) << channel << ": " << why;
    }
  }
  for (const auto& [channel, count] : decoded) EXPECT_GT(count, 0) << channel;
  // Not visual_labels: since this log was recorded it labels only what the
  // camera shows, so its replay here differs by the unseen entries; nor
  // fusion: it now writes the whole list at keyframes and HYPOTHESIS_CHANGES
  // at every tick, where this log has the whole list at every tick (a fresh
  // run's replay is exact: Replay.FusionAndVisualLabelsMatchTheRecordedRunExactly).
  for (const char* module : {"acoustic_labels", "geometry"}) {
    const auto replay = runCommand(binDir() + "/beft-replay " + log_path + " --module " + module, 120);
    EXPECT_EQ(replay.exit_code, 0) << module << "\n" << replay.output;
    EXPECT_NE(replay.output.find("EXACT MATCH"), std::string::npos) << replay.output;
  }
}

TEST(Render, WritesOneFramePerRenderedTickFromALog) {
  const std::string log_path = sourceDir() + "/tests/system/data/peek_6_ticks.lcmlog";
  const std::string dir = makeTempDir("render");
  const auto render = runCommand(binDir() + "/beft-replay " + log_path + " --to " + dir + "/frames", 120);
  ASSERT_EQ(render.exit_code, 0) << render.output;
  const auto listing = runCommand("ls " + dir + "/frames", 5).output;
  EXPECT_NE(listing.find("frame_00000.png"), std::string::npos) << listing;
  EXPECT_NE(listing.find("frame_00005.png"), std::string::npos) << listing;
  const auto header = runCommand("head -c 8 " + dir + "/frames/frame_00005.png | od -An -c", 5).output;
  EXPECT_NE(header.find("P   N   G"), std::string::npos) << header;
  const auto bad = runCommand(binDir() + "/beft-replay " + log_path + " --to " + dir + "/x.mp4 --module fusion", 30);
  EXPECT_NE(bad.exit_code, 0);  // --to and --module exclude each other
}

// --record-camera every:5 keeps the frames of ticks 0, 5, 10, ... and every
// other message; a replay of the vision expert says the log lacks the rest.
TEST(RecordCamera, EveryFifthTickKeepsExactlyThoseFramesAndAVisionReplaySaysWhatIsMissing) {
  const auto& full = shortYardRun();
  ASSERT_EQ(full.result.exit_code, 0) << full.result.output;
  std::string dir;
  std::vector<LoggedMessage> log;
  std::map<std::string, std::vector<int64_t>> frame_ticks;
  std::vector<int64_t> expected_ticks;
  for (int64_t tick = 0; tick < kShortTicks; tick += 5) expected_ticks.push_back(tick);
  // The recorder hears the run over UDP: a run whose log lost a frame is recorded again.
  for (int attempt = 0; attempt < 3; ++attempt) {
    dir = makeTempDir("record_camera");
    const auto result = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --max-ticks " +
                                       std::to_string(kShortTicks) + " --record-camera every:5 --no-report --out " + dir,
                                   300);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("camera frames recorded: every:5"), std::string::npos) << result.output;
    log = readLog(dir + "/run.lcmlog");
    frame_ticks.clear();
    for (const char* channel : {"CAMERA_COLOR", "CAMERA_DEPTH", "CAMERA_INSTANCE"})
      for (const auto& frame : messagesOn<beft::camera_frame_t>(log, channel))
        frame_ticks[channel].push_back(frame.tick);
    bool whole = true;
    for (const auto& [channel, ticks] : frame_ticks) whole = whole && ticks.size() == expected_ticks.size();
    if (whole) break;
  }
  ASSERT_EQ(frame_ticks.size(), 3u);
  for (const auto& [channel, ticks] : frame_ticks) EXPECT_EQ(ticks, expected_ticks) << channel;
  // Every data message is that of the run that kept every frame, once its
  // frames of the ticks left out are taken away.
  std::vector<LoggedMessage> full_sampled;
  for (const auto& event : full.log) {
    int64_t tick = 0;
    const bool frame = event.channel.rfind("CAMERA_", 0) == 0;
    if (!frame || (beft::wire::encodedTick(event.data.data(), event.data.size(), tick) && tick % 5 == 0))
      full_sampled.push_back(event);
  }
  const DataComparison comparison = compareDataMessages(full_sampled, log);
  EXPECT_GT(comparison.expected, 200u);
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;

  const auto vision = runCommand(binDir() + "/beft-replay " + dir + "/run.lcmlog --module vision", 120);
  EXPECT_EQ(vision.exit_code, 4) << vision.output;
  EXPECT_NE(vision.output.find("INCOMPLETE LOG"), std::string::npos) << vision.output;
  EXPECT_NE(vision.output.find("the log lacks inputs of " + std::to_string(kShortTicks - expected_ticks.size()) +
                               " of the " + std::to_string(kShortTicks) + " firings"),
            std::string::npos)
      << vision.output;
  EXPECT_NE(vision.output.find("CAMERA_DEPTH ("), std::string::npos) << vision.output;
  EXPECT_NE(vision.output.find("--record-camera"), std::string::npos) << vision.output;
  // An expert that reads no frame replays as from a full log.
  const auto fusion = runCommand(binDir() + "/beft-replay " + dir + "/run.lcmlog --module fusion", 120);
  EXPECT_EQ(fusion.exit_code, 0) << fusion.output;
  EXPECT_NE(fusion.output.find("EXACT MATCH"), std::string::npos) << fusion.output;
}
