#include "tests/system/two_hosts.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <sstream>

namespace beft::system_test {

namespace {

struct Shell {
  int exit_code = -1;
  std::string output;
};

// A short administrative command (ip, iptables): its output and exit code.
Shell shell(const std::string& command) {
  Shell result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  return result;
}

// Names unique on this machine: the process id, and a count within the process.
std::string nextTag() {
  static std::atomic<int> created{0};
  return std::to_string(getpid() % 100000) + "_" + std::to_string(created++ % 10);
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

}  // namespace

std::unique_ptr<TwoHosts> TwoHosts::create(std::string& why_not) {
  if (geteuid() != 0) {
    why_not = "needs root to create network namespaces";
    return nullptr;
  }
  const std::string tag = nextTag();
  const std::string sim = "beft_sim_" + tag, robot = "beft_robot_" + tag;
  const std::string sim_link = "bsim" + tag, robot_link = "brob" + tag;  // at most 15 characters
  const Shell setup = shell(
      "set -e; ip netns add " + sim + "; ip netns add " + robot + "; ip link add " + sim_link +
      " type veth peer name " + robot_link + "; ip link set " + sim_link + " netns " + sim + "; ip link set " +
      robot_link + " netns " + robot + "; ip -n " + sim + " addr add 10.231.0.1/24 dev " + sim_link + "; ip -n " +
      robot + " addr add 10.231.0.2/24 dev " + robot_link + "; for ns in " + sim + " " + robot +
      "; do ip -n $ns link set lo up; done; ip -n " + sim + " link set " + sim_link + " up; ip -n " + robot +
      " link set " + robot_link + " up; ip -n " + sim + " route add 224.0.0.0/4 dev " + sim_link + "; ip -n " +
      robot + " route add 224.0.0.0/4 dev " + robot_link);
  // Whatever part was made goes again with the object.
  std::unique_ptr<TwoHosts> hosts(new TwoHosts(sim, robot, sim_link, robot_link));
  if (setup.exit_code != 0) {
    why_not = "cannot create two linked network namespaces here:\n" + setup.output;
    return nullptr;
  }
  return hosts;
}

TwoHosts::TwoHosts(std::string sim, std::string robot, std::string sim_link, std::string robot_link)
    : sim_(std::move(sim)), robot_(std::move(robot)), sim_link_(std::move(sim_link)),
      robot_link_(std::move(robot_link)) {}

TwoHosts::~TwoHosts() {
  stopEverythingInside();
  for (const auto& ns : {sim_, robot_}) shell("ip netns del " + ns);
}

void TwoHosts::stopEverythingInside() const {
  for (const auto& ns : {sim_, robot_}) shell("ip netns pids " + ns + " 2>/dev/null | xargs -r kill -9");
}

std::string TwoHosts::dropIncoming(double probability) {
  if (probability < 0 || probability > 1) return "a probability is within [0, 1]";
  for (const auto& [ns, link] : {std::pair{sim_, sim_link_}, std::pair{robot_, robot_link_}}) {
    std::ostringstream rule;
    rule << "ip netns exec " << ns << " iptables -F INPUT";
    if (probability > 0)
      rule << " && ip netns exec " << ns << " iptables -A INPUT -i " << link
           << " -p udp -m statistic --mode random --probability " << probability << " -j DROP";
    const Shell result = shell(rule.str());
    if (result.exit_code != 0)
      return "cannot drop datagrams with iptables in a network namespace (" + rule.str() + "):\n" + result.output;
  }
  return "";
}

uint64_t TwoHosts::droppedDatagrams() const {
  uint64_t dropped = 0;
  for (const auto& ns : {sim_, robot_}) {
    // "pkts bytes target ...": the packets column of each DROP rule.
    std::istringstream lines(shell("ip netns exec " + ns + " iptables -nvxL INPUT").output);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream fields(line);
      uint64_t packets = 0;
      std::string bytes, target;
      if (fields >> packets >> bytes >> target && target == "DROP") dropped += packets;
    }
  }
  return dropped;
}

std::string distributedMissionCommand(const TwoHosts& hosts, const DistributedMission& mission) {
  const std::string launch = mission.bin_dir + "/beft-launch scenarios/launch/mission.xml --set expert_host=robot "
                             "--set seed=" + std::to_string(mission.seed) +
                             " --set max_ticks=" + std::to_string(mission.max_ticks) + " --lcm-url " +
                             quoted(kTwoHostsUrl) + (mission.extra_args.empty() ? "" : " " + mission.extra_args);
  const std::string& dir = mission.dir;
  // The robot side ends by itself when the run ends; the pause lets it say so.
  return "cd " + quoted(mission.source_dir) + " && (ip netns exec " + hosts.robot() + " " + launch +
         " --host robot > " + dir + "/robot.log 2>&1 &) && ip netns exec " + hosts.sim() + " " + launch +
         " --record " + dir + "/run.lcmlog > " + dir + "/sim.log 2>&1; status=$?; sleep 1; cat " + dir + "/sim.log " +
         dir + "/robot.log; exit $status";
}

}  // namespace beft::system_test
