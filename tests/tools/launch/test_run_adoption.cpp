// Which run a launch is: a fresh id for every launch that runs the arbiter,
// and, on the other hosts of a distributed run, the run the arbiter announces
// for the same launch, its beacon fresh (a replayed log's beacons are not).
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <beft/run_beacon_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/launch/free_port.hpp"
#include "lib/launch/launch_file.hpp"
#include "lib/launch/launch_identity.hpp"
#include "lib/launch/run_adoption.hpp"
#include "lib/transport/message_key.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_identity.hpp"

using namespace beft::launch;

namespace {

constexpr int64_t kDescription = 0x5eed;
constexpr int64_t kNow = 1'700'000'000'000'000;  // the fake wall clock [us]
constexpr int64_t kDay_us = 86'400'000'000;

beft::run_beacon_t beacon(int64_t run_id, int64_t utime, int64_t description = kDescription) {
  beft::run_beacon_t b{};
  b.utime = utime;
  b.run_id = run_id;
  b.host = "sim";
  b.pid = 42;
  b.description = description;
  b.started_utime = utime - 2'000'000;
  return b;
}

struct TempDir {
  std::string path;
  TempDir() {
    char pattern[] = "/tmp/beft_adoption_XXXXXX";
    path = mkdtemp(pattern);
  }
  ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string file = path + "/" + name;
    std::ofstream(file) << text;
    return file;
  }
};

// Listens on memq:// where the beacons were published first, on the fake
// clock. memq queues a message only for a channel somebody subscribed to, and
// hands it to every subscription there when handled: one is made first.
struct MemqAdoption {
  lcm::LCM lcm{"memq://"};
  std::vector<std::string> said;

  MemqAdoption() { lcm.subscribeFunction(std::string(beft::channels::kRunBeacons.name), &ignore, this); }
  static void ignore(const lcm::ReceiveBuffer*, const std::string&, MemqAdoption*) {}

  void publish(const beft::run_beacon_t& b) {
    ASSERT_EQ(beft::transport::publish(lcm, std::string(beft::channels::kRunBeacons.name), b), 0);
  }
  AnnouncedRun adopt(double timeout_s = 0.2, const beft::transport::MessageKey* key = nullptr) {
    AdoptionOptions options;
    options.key = key;
    options.timeout_s = timeout_s;
    options.settle_s = 0.05;
    options.wall_clock_us = [] { return kNow; };
    options.say = [this](const std::string& line) { said.push_back(line); };
    return adoptAnnouncedRun(lcm, kDescription, options);
  }
  std::string errorOfAdopting(const beft::transport::MessageKey* key = nullptr) {
    try {
      adopt(0.2, key);
    } catch (const LaunchError& e) {
      return e.what();
    }
    return "";
  }
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(AnnouncedRuns, TakesAFreshBeaconOfTheSameLaunchAndRefusesAStaleOne) {
  AnnouncedRuns runs(kDescription);
  EXPECT_EQ(runs.heard(beacon(0x11, kNow - 300'000), kNow), AnnouncedRuns::Verdict::kFresh);
  // A replayed log's beacon says when it was sent: yesterday.
  EXPECT_EQ(runs.heard(beacon(0x22, kNow - kDay_us), kNow), AnnouncedRuns::Verdict::kStale);
  // A clock far ahead is as far off as one behind.
  EXPECT_EQ(runs.heard(beacon(0x33, kNow + kBeaconFreshness_us + 1), kNow), AnnouncedRuns::Verdict::kStale);
  EXPECT_EQ(runs.heard(beacon(0x22, kNow - kDay_us + 500'000), kNow), AnnouncedRuns::Verdict::kStale);
  EXPECT_EQ(runs.heard(beacon(0x44, kNow + kBeaconFreshness_us), kNow), AnnouncedRuns::Verdict::kFresh);
  ASSERT_EQ(runs.fresh().size(), 2u);
  EXPECT_EQ(runs.fresh().begin()->second.run_id, 0x11);
  EXPECT_EQ(runs.fresh().begin()->second.host, "sim");
  EXPECT_EQ(runs.fresh().begin()->second.started_utime, kNow - 2'300'000);
  EXPECT_EQ(runs.staleBeacons(), 3u);
  EXPECT_EQ(runs.staleRuns(), (std::set<int64_t>{0x22, 0x33}));
  EXPECT_EQ(runs.otherLaunchBeacons(), 0u);
}

TEST(AnnouncedRuns, BeaconsOfAnotherLaunchOrWithoutIdOrDescriptionAreNotCandidates) {
  AnnouncedRuns runs(kDescription);
  EXPECT_EQ(runs.heard(beacon(0x11, kNow, kDescription + 1), kNow), AnnouncedRuns::Verdict::kOtherLaunch);
  EXPECT_EQ(runs.heard(beacon(0x11, kNow, 0), kNow), AnnouncedRuns::Verdict::kOtherLaunch);  // an arbiter started by hand
  EXPECT_EQ(runs.heard(beacon(0, kNow), kNow), AnnouncedRuns::Verdict::kOtherLaunch);        // a run without id
  EXPECT_TRUE(runs.fresh().empty());
  EXPECT_EQ(runs.otherLaunchBeacons(), 3u);
  EXPECT_EQ(runs.staleBeacons(), 0u);
}

TEST(RunAdoption, JoinsTheFreshRunAndSaysWhichStaleOneItRefused) {
  MemqAdoption memq;
  memq.publish(beacon(0x22, kNow - kDay_us));  // yesterday's run, its log replayed on the URL
  memq.publish(beacon(0x22, kNow - kDay_us + 500'000));
  memq.publish(beacon(0x7a, kNow, kDescription + 1));  // another launch on the URL
  memq.publish(beacon(0x11, kNow - 100'000));
  memq.publish(beacon(0x11, kNow));
  const AnnouncedRun run = memq.adopt();
  EXPECT_EQ(run.run_id, 0x11);
  EXPECT_EQ(run.pid, 42);
  ASSERT_EQ(memq.said.size(), 1u) << "a stale run is said once";
  EXPECT_TRUE(contains(memq.said[0], "refused the beacon of run 22")) << memq.said[0];
  EXPECT_TRUE(contains(memq.said[0], "86400.0 s away")) << memq.said[0];
  EXPECT_TRUE(contains(describeAnnouncedRun(run, kNow), "run 11 (arbiter pid 42 on host sim, launched 2.0 s ago)"))
      << describeAnnouncedRun(run, kNow);
}

TEST(RunAdoption, TwoFreshRunsOfTheSameLaunchAreRefusedAskingForTheRunId) {
  MemqAdoption memq;
  memq.publish(beacon(0x11, kNow));
  memq.publish(beacon(0x12, kNow - 1'000'000));
  const std::string error = memq.errorOfAdopting();
  EXPECT_TRUE(contains(error, "several runs of this launch")) << error;
  EXPECT_TRUE(contains(error, "run 11")) << error;
  EXPECT_TRUE(contains(error, "run 12")) << error;
  EXPECT_TRUE(contains(error, "--run-id")) << error;
}

TEST(RunAdoption, NoFreshRunWithinTheTimeoutFailsSayingWhatWasRefused) {
  MemqAdoption memq;
  const std::string silent = memq.errorOfAdopting();
  EXPECT_TRUE(contains(silent, "no run of this launch")) << silent;
  EXPECT_TRUE(contains(silent, "--run-id")) << silent;
  EXPECT_FALSE(contains(silent, "stale")) << silent;

  memq.publish(beacon(0x22, kNow - kDay_us));
  memq.publish(beacon(0x7a, kNow, kDescription + 1));
  const std::string replayed = memq.errorOfAdopting();
  EXPECT_TRUE(contains(replayed, "no run of this launch")) << replayed;
  EXPECT_TRUE(contains(replayed, "1 beacon(s) of it were refused as stale")) << replayed;
  EXPECT_TRUE(contains(replayed, "1 beacon(s) of other launches")) << replayed;
}

TEST(RunAdoption, AMalformedBeaconIsRefusedByTheGuard) {
  MemqAdoption memq;
  const std::array<uint8_t, 12> junk{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  beft::transport::publishEncoded(memq.lcm, std::string(beft::channels::kRunBeacons.name), junk.data(), junk.size());
  memq.publish(beacon(0x11, kNow));
  EXPECT_EQ(memq.adopt().run_id, 0x11);
}

// In a keyed run a beacon counts only with the key's tag: one sent without
// a key, or with another key, neither is joined nor makes two runs.
TEST(RunAdoption, AKeyedLaunchJoinsOnlyABeaconTaggedWithItsKey) {
  const beft::transport::MessageKey key = beft::transport::MessageKey::random();
  MemqAdoption memq;
  beft::transport::setProcessKey(std::nullopt);
  memq.publish(beacon(0x66, kNow));  // a host without the key
  beft::transport::setProcessKey(beft::transport::MessageKey::random());
  memq.publish(beacon(0x67, kNow));  // a host with another key
  beft::transport::setProcessKey(key);
  memq.publish(beacon(0x11, kNow));
  beft::transport::setProcessKey(std::nullopt);
  EXPECT_EQ(memq.adopt(0.2, &key).run_id, 0x11);
  ASSERT_FALSE(memq.said.empty());
  EXPECT_TRUE(contains(memq.said[0], "without a valid tag of this run's key")) << memq.said[0];

  memq.publish(beacon(0x66, kNow));
  const std::string error = memq.errorOfAdopting(&key);
  EXPECT_TRUE(contains(error, "1 beacon(s) without a valid tag of this run's key were refused")) << error;
  memq.publish(beacon(0x66, kNow));
  EXPECT_EQ(memq.adopt(0.2, nullptr).run_id, 0x66) << "without a key an untagged beacon is joined";
}

TEST(RunId, AFreshOneIsNeverZeroAndTakenAsChannelsShowIt) {
  std::set<int64_t> drawn;
  for (int i = 0; i < 100; ++i) {
    const int64_t id = beft::wire::freshRunId();
    ASSERT_GT(id, 0);
    drawn.insert(id);
    EXPECT_EQ(beft::wire::parseRunId(beft::wire::runIdText(id)), id);
    EXPECT_EQ(beft::wire::splitRunChannel(beft::wire::runChannel("VISION", id)).run_id, id);
  }
  EXPECT_EQ(drawn.size(), 100u);
}

TEST(LaunchIdentity, TwoLaunchesOfTheSameFileAreTwoRunsOfOneDescription) {
  TempDir dir;
  const auto file = dir.write("run.xml", R"(<launch>
  <arg name="seed" default="7"/>
  <process name="arbiter" command="true" args="${seed}" role="arbiter" lcm_url="0"/>
</launch>)");
  const LaunchSpec spec = loadLaunchFile(file, {});
  LaunchIdentityRequest request;
  request.launch_file = file;
  const LaunchIdentity first = identifyLaunch(spec, request);
  const LaunchIdentity second = identifyLaunch(spec, request);
  EXPECT_NE(first.run_id, 0);
  EXPECT_NE(first.run_id, second.run_id);
  EXPECT_EQ(first.origin.description, second.origin.description);
  EXPECT_EQ(first.origin.description, launchDescriptionOf(file, spec.args));
  EXPECT_GT(first.origin.started_utime, 0);
  // The description is the launch's, whatever the URL and hosts: other arguments, another one.
  EXPECT_EQ(launchDescriptionOf(file, {{"seed", "7"}, {"lcm_url", "udpm://a"}, {"expert_host", "robot"}}),
            launchDescriptionOf(file, {{"seed", "7"}}));
  EXPECT_NE(launchDescriptionOf(file, {{"seed", "8"}}), launchDescriptionOf(file, {{"seed", "7"}}));

  request.given_run_id = "1f3a";
  EXPECT_EQ(identifyLaunch(spec, request).run_id, 0x1f3a);
  request.given_run_id = "0";  // no run id: the plain channel names
  EXPECT_EQ(identifyLaunch(spec, request).run_id, 0);
  request.given_run_id = "not-hex";
  EXPECT_THROW(identifyLaunch(spec, request), LaunchError);
}

TEST(LaunchIdentity, OnlyTheArbitersHostDrawsTheId) {
  TempDir dir;
  const auto file = dir.write("run.xml", R"(<launch>
  <arg name="sim_host" default="local"/>
  <process name="expert" command="true" host="robot" lcm_url="0"/>
  <process name="arbiter" command="true" role="arbiter" host="${sim_host}" lcm_url="0"/>
</launch>)");
  const LaunchSpec spec = loadLaunchFile(file, {});
  EXPECT_TRUE(drawsTheRunId(spec, "local"));
  EXPECT_FALSE(drawsTheRunId(spec, "robot"));
  const auto without_arbiter = dir.write("none.xml", R"(<launch><process name="p" command="true" host="robot" lcm_url="0"/></launch>)");
  EXPECT_TRUE(drawsTheRunId(loadLaunchFile(without_arbiter, {}), "local"));
}

namespace {

struct Command {
  int exit_code = -1;
  std::string output;
};

Command run(const std::string& command) {
  Command result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string valueAfter(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  if (at == std::string::npos) return "";
  const auto start = at + key.size();
  return text.substr(start, text.find_first_of(" \n", start) - start);
}

}  // namespace

// beft-launch, twice on the same launch file: two runs, as its processes see them.
TEST(BeftLaunch, TwoLaunchesOfTheSameFileGetDifferentRunIds) {
  TempDir dir;
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="arbiter" command="sh" args="-c 'echo id=$BEFT_RUN_ID description=$BEFT_RUN_DESCRIPTION'" role="arbiter" lcm_url="0"/>
</launch>)");
  const std::string command = std::string(BEFT_LAUNCH_BINARY) + " " + file + " --lcm-url memq://";
  const Command first = run(command), second = run(command);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  ASSERT_EQ(second.exit_code, 0) << second.output;
  const std::string first_id = valueAfter(first.output, "[arbiter] id="), second_id = valueAfter(second.output, "[arbiter] id=");
  ASSERT_FALSE(first_id.empty()) << first.output;
  EXPECT_NE(first_id, second_id) << first.output << second.output;
  EXPECT_NE(first.output.find("as run " + first_id), std::string::npos) << first.output;
  const std::string description = valueAfter(first.output, "description=");
  EXPECT_FALSE(description.empty()) << first.output;
  EXPECT_EQ(description, valueAfter(second.output, "description="));
}

// beft-launch on a host without the arbiter, beside a replayed log's beacons
// of the same launch and the live arbiter's (sent here): it joins the live run.
TEST(BeftLaunch, AHostWithoutTheArbiterJoinsTheRunItAnnounces) {
  TempDir dir;
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="expert" command="sh" args="-c 'echo id=$BEFT_RUN_ID'" host="robot" lcm_url="0"/>
  <process name="arbiter" command="true" role="arbiter" lcm_url="0"/>
</launch>)");
  const int port = findFreeUdpPort(35000, 39999);
  ASSERT_GT(port, 0);
  const std::string url = "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
  const int64_t description = launchDescriptionOf(file, loadLaunchFile(file, {{"lcm_url", url}}).args);
  std::atomic<bool> done{false};
  std::thread arbiter([&] {
    lcm::LCM lcm(url);
    for (int i = 0; i < 1200 && !done; ++i) {  // twice a second, as an arbiter does; at most 60 s
      const int64_t now = std::chrono::duration_cast<std::chrono::microseconds>(
                              std::chrono::system_clock::now().time_since_epoch())
                              .count();
      beft::transport::publish(lcm, std::string(beft::channels::kRunBeacons.name), beacon(0x22, now - kDay_us, description));
      beft::transport::publish(lcm, std::string(beft::channels::kRunBeacons.name), beacon(0xabc1, now, description));
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
  const Command robot =
      run(std::string(BEFT_LAUNCH_BINARY) + " " + file + " --host robot --join-timeout 60 --lcm-url '" + url + "'");
  done = true;
  arbiter.join();
  ASSERT_EQ(robot.exit_code, 0) << robot.output;
  EXPECT_NE(robot.output.find("joining run abc1 (arbiter pid 42 on host sim"), std::string::npos) << robot.output;
  EXPECT_NE(robot.output.find("refused the beacon of run 22"), std::string::npos) << robot.output;
  EXPECT_NE(robot.output.find("[expert] id=abc1"), std::string::npos) << robot.output;
}

TEST(BeftLaunch, AHostWithoutTheArbiterFailsClearlyWhenNoRunIsAnnounced) {
  TempDir dir;
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="expert" command="sh" args="-c 'echo started'" host="robot" lcm_url="0"/>
  <process name="arbiter" command="true" role="arbiter" lcm_url="0"/>
</launch>)");
  const Command robot = run(std::string(BEFT_LAUNCH_BINARY) + " " + file + " --host robot --join-timeout 0.3 --lcm-url memq://");
  EXPECT_EQ(robot.exit_code, 2) << robot.output;
  EXPECT_NE(robot.output.find("no run of this launch"), std::string::npos) << robot.output;
  EXPECT_EQ(robot.output.find("[expert] started"), std::string::npos) << "started before it knew its run";
}
