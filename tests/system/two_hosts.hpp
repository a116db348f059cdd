// Two machines on one: two network namespaces joined by a virtual Ethernet
// link, the simulation side ("sim": blackboard, planner, world, arbiter,
// recorder) on one and the experts and task executor ("robot") on the other,
// with multicast routed over the link, so LCM with ttl=1 goes between them as
// between two hosts. Used by the system tests (test_distributed,
// test_lossy_link) and by beft-bench-faults. Needs root and `ip netns`;
// dropping datagrams needs iptables' statistic match as well (the kernel
// need not have netem).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace beft::system_test {

class TwoHosts {
 public:
  // Creates both namespaces and the link; null, with `why_not` said, where
  // that cannot be done here (not root, no namespaces).
  static std::unique_ptr<TwoHosts> create(std::string& why_not);
  // Stops everything inside and deletes them.
  ~TwoHosts();
  TwoHosts(const TwoHosts&) = delete;
  TwoHosts& operator=(const TwoHosts&) = delete;

  const std::string& sim() const { return sim_; }
  const std::string& robot() const { return robot_; }

  // From now on each namespace drops `probability` [0..1] of the UDP
  // datagrams it receives over the link, at random (`iptables -m statistic`),
  // so every message between the hosts is lost that often each way. Replaces
  // an earlier loss; 0 drops nothing. "" when set, else why not.
  std::string dropIncoming(double probability);
  // UDP datagrams the loss rule has dropped since it was set, both namespaces together.
  uint64_t droppedDatagrams() const;
  // Kills whatever still runs in them: a side that missed the end of a run.
  void stopEverythingInside() const;

 private:
  TwoHosts(std::string sim, std::string robot, std::string sim_link, std::string robot_link);

  std::string sim_, robot_, sim_link_, robot_link_;
};

// A mission of the launch file over the two hosts, as two machines start it:
// each side runs `beft-launch scenarios/launch/mission.xml --set
// expert_host=robot`, the robot side with `--host robot`.
struct DistributedMission {
  std::string bin_dir;     // where beft-launch is
  std::string source_dir;  // the repository (the launch file names its files from there)
  std::string dir;         // the run's folder: run.lcmlog (recorded on the sim side), sim.log, robot.log
  uint64_t seed = 7;
  int max_ticks = 150;
  std::string extra_args;  // for both sides' beft-launch
};

// The shell command of that run: the robot side in the background, the sim
// side in the foreground recording dir/run.lcmlog; when the sim side ends it
// prints both sides' output and exits with the sim side's status.
std::string distributedMissionCommand(const TwoHosts& hosts, const DistributedMission& mission);

// The LCM URL of the distributed runs: the default group and port (each
// namespace has ports of its own: nothing else there can collide), ttl=1,
// and a receive buffer for camera frames.
inline constexpr const char* kTwoHostsUrl = "udpm://239.255.76.67:7667?ttl=1&recv_buf_size=8388608";

}  // namespace beft::system_test
