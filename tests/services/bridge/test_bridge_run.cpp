// A real yard run watched by the worst viewers: one that subscribes to every
// topic and never reads, one that sends garbage all along, and twenty that
// read a little and then stop. The run (paced in real time, as --view does)
// writes the data messages of the same run unwatched and at full speed, and
// the bridge's memory stays bounded (printed).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "lib/launch/tcp_port.hpp"
#include "tests/services/bridge/bridge_client.hpp"
#include "tests/system/run_support.hpp"

using namespace beft::system_test;
using beft::bridge_test::WsClient;
using nlohmann::json;

namespace {

constexpr int kTicks = 300;
constexpr int kSeed = 11;
constexpr int kReaders = 20;

std::string yardRun(const std::string& dir, const std::string& extra) {
  return binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --seed " + std::to_string(kSeed) +
         " --max-ticks " + std::to_string(kTicks) + " --no-report --out " + dir + " " + extra;
}

// A command in the background, its output in a file; killed if still running at the end.
class Background {
 public:
  Background(const std::string& command, const std::string& output) {
    pid_ = fork();
    if (pid_ == 0) {
      setpgid(0, 0);
      execl("/bin/sh", "sh", "-c", (command + " > " + output + " 2>&1").c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
  }
  ~Background() {
    if (pid_ > 0 && !exited_) {
      kill(-pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  bool running() {
    if (exited_) return false;
    exited_ = waitpid(pid_, &status_, WNOHANG) == pid_;
    return !exited_;
  }
  int exitCode() {
    while (running()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : -1;
  }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  int status_ = 0;
};

// VmRSS of the beft-bridge serving `port` [kB]; 0 if it is not found.
long bridgeResidentKilobytes(int port) {
  const auto found = runCommand("pgrep -f 'beft-[b]ridge --port " + std::to_string(port) + "' | head -1", 10);
  if (found.exit_code != 0 || found.output.empty()) return 0;
  std::ifstream status("/proc/" + std::to_string(std::stoi(found.output)) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return 0;
}

json subscriptionsToEveryTopic(const json& advertise) {
  json subscriptions = json::array();
  uint32_t id = 1;
  for (const auto& channel : advertise["channels"])
    subscriptions.push_back({{"id", id++}, {"channelId", channel["id"]}});
  return subscriptions;
}

// Garbage of every kind a client can send: none of it may reach the run.
void sendGarbage(WsClient& client, int round) {
  client.sendText("{\"op\": \"subscribe\", \"subscriptions\": [{\"id\": -1, \"channelId\": 1e40}]}");
  client.sendText(std::string("not json {") + std::to_string(round));
  std::string bytes(64 + round % 200, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 131 + round * 7) & 0xff);
  client.sendBinary(bytes);
  client.sendBinary(std::string("\x01\x07\x00\x00\x00{\"command\":9}", 17));  // a publish on no advertised channel
}

}  // namespace

TEST(WatchedRun, WorstViewersChangeNoDataMessageAndTheBridgeStaysBounded) {
  const std::string plain_dir = makeTempDir("watched_plain");
  const auto plain = runCommand(yardRun(plain_dir, "--fast"), 600);
  ASSERT_EQ(plain.exit_code, 0) << plain.output;

  const std::string viewed_dir = makeTempDir("watched_viewed");
  const int port = beft::launch::findFreeTcpPort();
  ASSERT_GT(port, 0);
  // At the real-time pace (30 s), so that every viewer is connected long
  // before the run ends, however slowly this machine starts them.
  Background run(yardRun(viewed_dir, "--view --port " + std::to_string(port)), viewed_dir + "/run_output.txt");
  ASSERT_TRUE(beft::launch::waitForTcpListener("127.0.0.1", port, 120)) << "the bridge never listened";

  // The idle viewer holds the run while the others connect, then lets it go.
  WsClient idle("127.0.0.1", port, "/", "", 64 * 1024);
  idle.readOp("serverInfo");
  const json advertise = idle.readOp("advertise");
  idle.advertise(1, "/beft/run_control");
  idle.publish(1, {{"action", "pause"}});
  idle.sendJson({{"op", "subscribe"}, {"subscriptions", subscriptionsToEveryTopic(advertise)}});
  WsClient garbage("127.0.0.1", port);
  std::vector<std::unique_ptr<WsClient>> readers;
  for (int i = 0; i < kReaders; ++i) {
    readers.push_back(std::make_unique<WsClient>("127.0.0.1", port));
    readers.back()->readOp("serverInfo");
    readers.back()->sendJson({{"op", "subscribe"}, {"subscriptions", subscriptionsToEveryTopic(advertise)}});
  }
  idle.publish(1, {{"action", "run"}});
  for (auto& reader : readers) EXPECT_FALSE(reader->read().bytes.empty());  // served, then never read again

  long peak_kb = 0;
  for (int round = 0; run.running(); ++round) {
    try {
      sendGarbage(garbage, round);
    } catch (const std::exception&) {  // the bridge may close a connection that misbehaves
    }
    if (round % 10 == 0) peak_kb = std::max(peak_kb, bridgeResidentKilobytes(port));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::printf("[watched run] beft-bridge with %d viewers that stopped reading and one sending garbage: %.1f MB "
              "resident at most\n", kReaders + 1, peak_kb / 1024.0);
  ASSERT_EQ(run.exitCode(), 0) << "see " << viewed_dir << "/run_output.txt";
  EXPECT_GT(peak_kb, 0) << "the bridge was never found";
  EXPECT_LT(peak_kb, 400 * 1024);

  const DataComparison comparison =
      compareDataMessages(readLog(plain_dir + "/run.lcmlog"), readLog(viewed_dir + "/run.lcmlog"));
  EXPECT_GT(comparison.expected, static_cast<std::size_t>(kTicks * 10));
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
}
