// The arbiter's programs as real processes: beft-net-check on the
// repository's and crafted nets, and beft-arbiter on its own UDP port with an
// in-test LCM responder standing in for the experts.
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/marking_t.hpp>
#include <beft/run_beacon_t.hpp>
#include <beft/run_status_t.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "lib/common/channels.hpp"
#include "services/arbiter/lcm_arbiter.hpp"
#include "lib/common/lcm_url.hpp"

namespace {

const std::string kNets = std::string(BEFT_SOURCE_DIR) + "/scenarios/nets/";
const std::string kTestNets = std::string(BEFT_TEST_NETS_DIR) + "/";
using Clock = std::chrono::steady_clock;

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string tempPath(const std::string& name) {
  static int next = 0;  // several children at once get files of their own
  return "/tmp/beft_test_arbiter_" + std::to_string(getpid()) + "_" + std::to_string(next++) + "_" + name;
}

// A child process with stdout and stderr in files.
class Child {
 public:
  explicit Child(const std::vector<std::string>& argv)
      : out_path_(tempPath("out.txt")), err_path_(tempPath("err.txt")) {
    // Everything the child needs is prepared before fork(): the parent may
    // have LCM threads, so the child only calls async-signal-safe functions.
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const int out = open(out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out, STDOUT_FILENO);
      dup2(err, STDERR_FILENO);
      execv(args[0], args.data());
      _exit(127);
    }
    close(out);
    close(err);
  }
  ~Child() {
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    std::remove(out_path_.c_str());
    std::remove(err_path_.c_str());
  }

  // True once the child has exited (exit code in exitCode()).
  bool poll() {
    if (exited_) return true;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    return exited_;
  }
  bool waitFor(double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (!poll() && Clock::now() < deadline) usleep(10000);
    return exited_;
  }
  int exitCode() const { return exit_code_; }
  std::string out() const { return readFile(out_path_); }
  std::string err() const { return readFile(err_path_); }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  int exit_code_ = -1;
  std::string out_path_, err_path_;
};

struct Finished {
  int exit_code;
  std::string out, err;
};

Finished runToEnd(const std::vector<std::string>& argv, double timeout_s = 60.0) {
  Child child(argv);
  EXPECT_TRUE(child.waitFor(timeout_s)) << argv[0] << " did not end within " << timeout_s << " s";
  return {child.exitCode(), child.out(), child.err()};
}

bool contains(const std::string& text, const std::string& fragment) {
  return text.find(fragment) != std::string::npos;
}

// ---- beft-net-check ----

TEST(NetCheckProcess, DefaultNetIsSafeAndLive) {
  const Finished run = runToEnd({BEFT_NET_CHECK_BIN, kNets + "default.pnml"});
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
  EXPECT_TRUE(contains(run.out, "10 fire an expert, 2 silent")) << run.out;
  EXPECT_TRUE(contains(run.out, "reachable markings: 46")) << run.out;
  EXPECT_TRUE(contains(run.out, "1-safe: yes")) << run.out;
  EXPECT_TRUE(contains(run.out, "dead transitions: none")) << run.out;
  EXPECT_TRUE(contains(run.out, "tick end reachable from every reachable marking: yes")) << run.out;
  EXPECT_TRUE(contains(run.out, "result: OK, 1-safe and live")) << run.out;
  for (const char* other : {"experts_only.pnml", "sequential.pnml", "concurrent.pnml"})
    EXPECT_EQ(runToEnd({BEFT_NET_CHECK_BIN, kNets + other}).exit_code, 0) << other;
}

TEST(NetCheckProcess, ReportsWhatIsWrong) {
  const Finished unsafe = runToEnd({BEFT_NET_CHECK_BIN, kTestNets + "unsafe.pnml"});
  EXPECT_EQ(unsafe.exit_code, 1);
  EXPECT_TRUE(contains(unsafe.out, "place 'p_objects' holds 2 tokens")) << unsafe.out;
  EXPECT_TRUE(contains(unsafe.out, "result: NOT OK: not 1-safe")) << unsafe.out;

  const Finished dead = runToEnd({BEFT_NET_CHECK_BIN, kTestNets + "dead_transition.pnml"});
  EXPECT_EQ(dead.exit_code, 1);
  EXPECT_TRUE(contains(dead.out, "dead_transition.pnml:13: t_audio (audio) can never fire")) << dead.out;

  const Finished deadlock = runToEnd({BEFT_NET_CHECK_BIN, kTestNets + "deadlock.pnml"});
  EXPECT_EQ(deadlock.exit_code, 1);
  EXPECT_TRUE(contains(deadlock.out, "deadlock markings: 1")) << deadlock.out;
  EXPECT_TRUE(contains(deadlock.out, "reached by: start t_world, end t_world, start t_audio, end t_audio"))
      << deadlock.out;
  EXPECT_TRUE(contains(deadlock.out, "tick end reachable from every reachable marking: NO")) << deadlock.out;

  const Finished unbounded = runToEnd({BEFT_NET_CHECK_BIN, kTestNets + "unbounded.pnml"});
  EXPECT_EQ(unbounded.exit_code, 1);
  EXPECT_TRUE(contains(unbounded.out, "result: NOT OK: unbounded")) << unbounded.out;

  const Finished bad = runToEnd({BEFT_NET_CHECK_BIN, kTestNets + "bad_arc.pnml"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(contains(bad.err, "bad_arc.pnml:9: arc 'a2': unknown target 'p_missing'")) << bad.err;
}

// ---- beft-arbiter ----

std::string uniqueUrl(int offset) {
  return beft::lcmUrlForPort(21000 + static_cast<int>((getpid() * 4 + offset) % 20000));
}

// Stands in for every expert on LCM: heartbeats, and DONE for every FIRE.
class Responder {
 public:
  Responder(const std::string& url, std::vector<std::string> experts) : lcm_(url), experts_(std::move(experts)) {
    lcm_.subscribe(beft::channels::kFire, &Responder::onFire, this)->setQueueCapacity(10000);
    lcm_.subscribe(beft::channels::kRunStatus, &Responder::onStatus, this)->setQueueCapacity(1000);
    lcm_.subscribe(beft::channels::kMarking, &Responder::onMarking, this)->setQueueCapacity(10000);
  }

  bool good() { return lcm_.good(); }
  // Whether to ignore this copy of a FIRE (copy 0 is the first to arrive).
  std::function<bool(const beft::fire_t&, int copy)> drop_fire;
  // Experts that are gone (no heartbeat, no answer), asked at every message.
  std::function<bool(const std::string& expert)> gone;
  // Called for every FIRE that arrives (e.g. to publish a stop request).
  std::function<void(lcm::LCM&, const beft::fire_t&)> on_fire;

  // Serves until the child ends (or the time runs out).
  void serve(Child& child, double timeout_s) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_s);
    auto next_heartbeat = Clock::now();
    while (!child.poll() && Clock::now() < deadline) {
      if (Clock::now() >= next_heartbeat) {
        for (const auto& name : experts_) {
          if (gone && gone(name)) continue;
          beft::heartbeat_t beat{};
          beat.process = name;
          beat.pid = getpid();
          beat.host = "test";
          beat.last_firing_id = -1;
          beat.state = "idle";
          lcm_.publish(beft::channels::kHeartbeat, &beat);
        }
        next_heartbeat += std::chrono::milliseconds(200);
      }
      lcm_.handleTimeout(5);
    }
    while (lcm_.handleTimeout(0) > 0) {
    }
  }

  struct Event {
    char kind;  // 'F' first FIRE of an id, 'D' DONE sent
    std::string expert;
    int64_t tick;
    int64_t firing_id;
  };
  std::vector<Event> events;
  std::map<int64_t, int> copies;  // FIRE copies received per firing id
  std::vector<beft::run_status_t> statuses;
  int markings = 0;
  std::vector<std::pair<int64_t, std::vector<std::string>>> running_sets;  // per MARKING: tick, experts running

 private:
  void onFire(const lcm::ReceiveBuffer*, const std::string&, const beft::fire_t* fire) {
    const int copy = copies[fire->firing_id]++;
    if (gone && gone(fire->expert)) return;
    if (drop_fire && drop_fire(*fire, copy)) return;
    if (!answered_.count(fire->firing_id)) events.push_back({'F', fire->expert, fire->tick, fire->firing_id});
    if (on_fire) on_fire(lcm_, *fire);
    beft::done_t done{};
    done.utime = fire->utime;
    done.expert = fire->expert;
    done.tick = fire->tick;
    done.firing_id = fire->firing_id;
    done.outcome = beft::done_t::OUTCOME_OK;
    done.duration = 0.0;
    if (answered_.insert(fire->firing_id).second) events.push_back({'D', fire->expert, fire->tick, fire->firing_id});
    lcm_.publish(beft::channels::kDone, &done);
  }
  void onStatus(const lcm::ReceiveBuffer*, const std::string&, const beft::run_status_t* status) {
    statuses.push_back(*status);
  }
  void onMarking(const lcm::ReceiveBuffer*, const std::string&, const beft::marking_t* marking) {
    ++markings;
    running_sets.emplace_back(marking->tick, marking->running);
  }

  lcm::LCM lcm_;
  std::vector<std::string> experts_;
  std::set<int64_t> answered_;
};

const std::vector<std::string> kExpertsOnly = {"world", "geometry", "vision", "audio",
                                               "visual_labels", "acoustic_labels", "fusion"};
const std::vector<std::vector<std::string>> kExpertsOnlyStages = {
    {"world"}, {"geometry", "vision", "audio"}, {"visual_labels", "acoustic_labels"}, {"fusion"}};

int positionOf(const std::vector<Responder::Event>& events, char kind, const std::string& expert, int64_t tick) {
  for (size_t i = 0; i < events.size(); ++i)
    if (events[i].kind == kind && events[i].expert == expert && events[i].tick == tick) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> arbiterArgs(const std::string& url, const std::string& net,
                                     const std::vector<std::string>& extra) {
  std::vector<std::string> args = {BEFT_ARBITER_BIN, "--net", net, "--lcm-url", url, "--startup-timeout", "10"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

const beft::run_status_t* finalStatus(const std::vector<beft::run_status_t>& statuses) {
  for (const auto& s : statuses)
    if (s.state == beft::run_status_t::STATE_FINISHED || s.state == beft::run_status_t::STATE_FAILED) return &s;
  return nullptr;
}

TEST(ArbiterProcess, RunsTheExpertsOnlyNetInLockstep) {
  const std::string url = uniqueUrl(0);
  const std::string csv = tempPath("firings.csv");
  const int64_t ticks = 20;
  Responder responder(url, kExpertsOnly);
  ASSERT_TRUE(responder.good());
  // Vision's first FIRE of tick 3 is lost on the way: the re-send must bring it.
  responder.drop_fire = [](const beft::fire_t& f, int copy) { return f.expert == "vision" && f.tick == 3 && copy == 0; };
  Child arbiter(arbiterArgs(url, kNets + "experts_only.pnml",
                            {"--max-ticks", std::to_string(ticks), "--dt", "0.05", "--firing-log", csv}));
  responder.serve(arbiter, 60.0);
  ASSERT_TRUE(arbiter.poll()) << "the arbiter did not end\n" << arbiter.err();
  EXPECT_EQ(arbiter.exitCode(), 0) << arbiter.err();

  const auto& events = responder.events;
  for (int64_t k = 0; k < ticks; ++k) {
    for (size_t s = 0; s < kExpertsOnlyStages.size(); ++s) {
      int last_done = -1;
      for (const auto& expert : kExpertsOnlyStages[s]) {
        ASSERT_GE(positionOf(events, 'F', expert, k), 0) << expert << " tick " << k;
        last_done = std::max(last_done, positionOf(events, 'D', expert, k));
      }
      // The experts of a stage were started together, in one step.
      const std::pair<int64_t, std::vector<std::string>> together{k, kExpertsOnlyStages[s]};
      EXPECT_NE(std::find(responder.running_sets.begin(), responder.running_sets.end(), together),
                responder.running_sets.end())
          << "stage " << s << " of tick " << k << " never ran all at once";
      const bool last_stage = s + 1 == kExpertsOnlyStages.size();
      if (last_stage && k + 1 == ticks) continue;
      for (const auto& expert : last_stage ? kExpertsOnlyStages[0] : kExpertsOnlyStages[s + 1])
        EXPECT_LT(last_done, positionOf(events, 'F', expert, last_stage ? k + 1 : k)) << expert << " tick " << k;
    }
  }
  // Each expert exactly once per tick, nothing beyond the last tick.
  std::map<std::pair<std::string, int64_t>, int> firings;
  for (const auto& e : events)
    if (e.kind == 'F') ++firings[{e.expert, e.tick}];
  EXPECT_EQ(firings.size(), kExpertsOnly.size() * ticks);
  for (const auto& [key, count] : firings) EXPECT_EQ(count, 1) << key.first << " tick " << key.second;

  const auto vision3 = std::find_if(events.begin(), events.end(), [](const Responder::Event& e) {
    return e.kind == 'F' && e.expert == "vision" && e.tick == 3;
  });
  ASSERT_NE(vision3, events.end());
  EXPECT_GE(responder.copies[vision3->firing_id], 2);  // the lost FIRE was sent again

  const beft::run_status_t* final_status = finalStatus(responder.statuses);
  ASSERT_NE(final_status, nullptr);
  EXPECT_EQ(final_status->state, beft::run_status_t::STATE_FINISHED);
  EXPECT_EQ(final_status->message, "finished after 20 ticks");
  EXPECT_EQ(final_status->utime, (ticks - 1) * 50000);
  EXPECT_GT(responder.markings, static_cast<int>(ticks));

  // The firing log: one CSV row and one stdout line per firing.
  std::istringstream rows(readFile(csv));
  std::string row;
  std::getline(rows, row);
  EXPECT_EQ(row.rfind("tick,firing_id,expert,transition,", 0), 0u) << row;
  int ok_rows = 0;
  while (std::getline(rows, row)) ok_rows += contains(row, ",ok,") ? 1 : 0;
  EXPECT_EQ(ok_rows, static_cast<int>(kExpertsOnly.size() * ticks));
  std::istringstream lines(arbiter.out());
  int firing_lines = 0;
  std::string line;
  while (std::getline(lines, line)) firing_lines += line.rfind("tick ", 0) == 0 && contains(line, " ok ") ? 1 : 0;
  EXPECT_EQ(firing_lines, static_cast<int>(kExpertsOnly.size() * ticks));
  std::remove(csv.c_str());
}

TEST(ArbiterProcess, ADeadExpertEndsTheRunByTheNetsPolicy) {
  const std::string url = uniqueUrl(1);
  Responder responder(url, kExpertsOnly);
  ASSERT_TRUE(responder.good());
  bool audio_gone = false;
  // Audio dies when it is fired in tick 4: no answer, no heartbeat from then on.
  responder.gone = [&audio_gone](const std::string& expert) { return expert == "audio" && audio_gone; };
  responder.on_fire = [&audio_gone](lcm::LCM&, const beft::fire_t& f) {
    if (f.expert == "world" && f.tick == 4) audio_gone = true;
  };
  Child arbiter(arbiterArgs(url, kNets + "experts_only.pnml", {"--heartbeat-timeout", "0.5"}));
  responder.serve(arbiter, 60.0);
  ASSERT_TRUE(arbiter.poll()) << "the arbiter did not end\n" << arbiter.err();
  EXPECT_EQ(arbiter.exitCode(), 1) << arbiter.err();
  const beft::run_status_t* final_status = finalStatus(responder.statuses);
  ASSERT_NE(final_status, nullptr);
  EXPECT_EQ(final_status->state, beft::run_status_t::STATE_FAILED);
  EXPECT_EQ(final_status->tick, 4);
  EXPECT_TRUE(contains(final_status->message, "audio (tick 4")) << final_status->message;
  EXPECT_TRUE(contains(final_status->message, "no heartbeat")) << final_status->message;
  EXPECT_TRUE(contains(final_status->message, "after 1 retries")) << final_status->message;
  EXPECT_EQ(positionOf(responder.events, 'F', "visual_labels", 4), -1);
  EXPECT_TRUE(contains(arbiter.err(), "run FAILED in tick 4")) << arbiter.err();
}

// Two runs on one URL by mistake: each arbiter hears the other's beacon and
// says so within a second, while neither takes the other's messages.
TEST(ArbiterProcess, TwoArbitersOnOneUrlBothSaySoWithinASecond) {
  const std::string url = uniqueUrl(3);
  auto withRun = [&](const std::string& run_id) {
    std::vector<std::string> args = {"/usr/bin/env", "BEFT_RUN_ID=" + run_id};
    for (const auto& arg : arbiterArgs(url, kNets + "experts_only.pnml", {})) args.push_back(arg);
    args.back() = "1.5";  // --startup-timeout
    return args;
  };
  Child first(withRun("a1"));
  Child second(withRun("b2"));
  // Both wait for experts that never come, and fail after 1.5 s.
  ASSERT_TRUE(first.waitFor(20.0));
  ASSERT_TRUE(second.waitFor(20.0));
  EXPECT_TRUE(contains(first.err(), "another run (run b2")) << first.err();
  EXPECT_TRUE(contains(second.err(), "another run (run a1")) << second.err();
  EXPECT_TRUE(contains(first.err(), "shares this LCM URL with this run (run a1)")) << first.err();
}

// The beacon names the launch the run is of, as the launcher set it, so that
// a host of a distributed run without the arbiter can join the run.
TEST(ArbiterProcess, ItsBeaconNamesTheLaunchAndWhenItStarted) {
  const std::string url = uniqueUrl(8);
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  struct Heard {
    std::vector<beft::run_beacon_t> beacons;
    void on(const lcm::ReceiveBuffer*, const std::string&, const beft::run_beacon_t* beacon) {
      beacons.push_back(*beacon);
    }
  } heard;
  lcm.subscribe(std::string(beft::channels::kRunBeacons.name), &Heard::on, &heard);
  std::vector<std::string> args = {"/usr/bin/env", "BEFT_RUN_ID=c3", "BEFT_RUN_DESCRIPTION=5eed",
                                   "BEFT_RUN_STARTED=1700000000000000"};
  for (const auto& arg : arbiterArgs(url, kNets + "experts_only.pnml", {})) args.push_back(arg);
  args.back() = "1.5";  // --startup-timeout: it waits for experts that never come
  Child arbiter(args);
  for (int i = 0; i < 400 && heard.beacons.empty(); ++i) lcm.handleTimeout(50);  // twice a second; at most 20 s
  ASSERT_TRUE(arbiter.waitFor(20.0));
  ASSERT_FALSE(heard.beacons.empty()) << arbiter.err();
  EXPECT_EQ(heard.beacons[0].run_id, 0xc3);
  EXPECT_EQ(heard.beacons[0].description, 0x5eed);
  EXPECT_EQ(heard.beacons[0].started_utime, 1'700'000'000'000'000);
}

TEST(ArbiterProcess, StopRequestEndsTheRunAfterTheTick) {
  const std::string url = uniqueUrl(2);
  Responder responder(url, kExpertsOnly);
  ASSERT_TRUE(responder.good());
  responder.on_fire = [](lcm::LCM& lcm, const beft::fire_t& f) {
    if (f.expert != "world" || f.tick != 5) return;
    beft::run_status_t stop{};
    stop.tick = f.tick;
    stop.state = beft::run_status_t::STATE_FINISHED;
    stop.message = "enough for this test";
    lcm.publish(beft::channels::kStopRequest, &stop);
  };
  Child arbiter(arbiterArgs(url, kNets + "experts_only.pnml", {"--max-ticks", "0", "--quiet"}));
  responder.serve(arbiter, 60.0);
  ASSERT_TRUE(arbiter.poll()) << "the arbiter did not end\n" << arbiter.err();
  EXPECT_EQ(arbiter.exitCode(), 0) << arbiter.err();
  const beft::run_status_t* final_status = finalStatus(responder.statuses);
  ASSERT_NE(final_status, nullptr);
  EXPECT_EQ(final_status->message, "stopped on request after 6 ticks: enough for this test");
  EXPECT_GE(positionOf(responder.events, 'D', "fusion", 5), 0);  // tick 5 was completed
  EXPECT_EQ(positionOf(responder.events, 'F', "world", 6), -1);
  EXPECT_EQ(arbiter.out(), "");  // --quiet
}

TEST(ArbiterEventQueue, PollsThenSleepsWithinTheTimeOutAndMissesNothing) {
  const std::string url = uniqueUrl(7);
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  beft::arbiter::ArbiterInbox inbox;
  beft::arbiter::ArbiterEventQueue queue(lcm, url, inbox);
  EXPECT_NE(queue.description().find("receiving only DONE, HEARTBEAT, STOP_REQUEST"), std::string::npos)
      << queue.description();
  // Nothing comes: the wait, poll included, lasts the time-out and no longer.
  auto start = Clock::now();
  ASSERT_TRUE(queue.receive(60, 20000));
  auto waited = Clock::now() - start;
  EXPECT_TRUE(queue.empty());
  EXPECT_GE(waited, std::chrono::milliseconds(55));
  EXPECT_LT(waited, std::chrono::milliseconds(60 + 500)) << "the poll counted against the time-out";
  // A DONE sent while it polls, one while it sleeps: both are taken.
  for (const int delay_ms : {2, 40}) {
    beft::arbiter::ArbiterInbox inbox;
    beft::arbiter::ArbiterEventQueue queue(lcm, url, inbox);
    std::thread sender([&url, delay_ms] {
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
      lcm::LCM lcm_sender(url);
      beft::done_t done{};
      done.expert = "vision";
      done.firing_id = delay_ms;
      lcm_sender.publish(beft::channels::kDone, &done);
    });
    start = Clock::now();
    bool got = false;
    while (!got && Clock::now() - start < std::chrono::seconds(3)) {
      ASSERT_TRUE(queue.receive(100, 10000));
      got = !queue.empty();
    }
    sender.join();
    EXPECT_TRUE(got) << "DONE sent after " << delay_ms << " ms";
  }
}

TEST(ArbiterProcess, RefusesABadNetWithItsLine) {
  const Finished run = runToEnd(arbiterArgs(uniqueUrl(3), kTestNets + "bad_arc.pnml", {}));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "bad_arc.pnml:9: arc 'a2': unknown target 'p_missing'")) << run.err;
}

}  // namespace
