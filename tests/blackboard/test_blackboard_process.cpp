// beft-blackboard as a real process on its own UDP port: a late client gets
// the latest message of each channel, and beft-blackboard-dump prints them.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include <beft/fire_t.hpp>
#include <beft/geometry_percepts_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/robot_state_t.hpp>

#include "blackboard/snapshot_client.hpp"
#include "lib/common/lcm_url.hpp"

extern char** environ;

namespace {

// A port of this test process alone: tests run in parallel, each in its own process.
std::string uniqueUrl(int salt) {
  const int port = 21000 + static_cast<int>((static_cast<unsigned>(getpid()) * 4u + static_cast<unsigned>(salt)) % 20000u);
  return beft::lcmUrlForPort(port);
}

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("beft_test_" + name + "_" + std::to_string(getpid()) + ".txt"))
      .string();
}

std::string readFile(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// A child process with its stderr in a file; stopped with SIGTERM.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string>& args, const std::string& stderr_path) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<char*> argv;
    for (const auto& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  ~ChildProcess() {
    if (pid_ > 0) stop();
  }
  bool started() const { return pid_ > 0; }
  // SIGTERM, then the exit status (or -1 if it did not exit normally).
  int stop() {
    if (pid_ <= 0) return -1;
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

 private:
  pid_t pid_ = -1;
};

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

CommandResult runCommand(const std::string& command) {
  const std::string err_path = tempPath("command_stderr");
  CommandResult result;
  FILE* pipe = popen((command + " 2>" + err_path).c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.err = readFile(err_path);
  std::remove(err_path.c_str());
  return result;
}

beft::robot_state_t robotState(int i) {
  beft::robot_state_t state{};
  state.utime = i * 100000;
  state.tick = i;
  state.x = 1.25 * i;
  state.y = -3.5;
  state.last_command = "goto " + std::to_string(i);
  return state;
}

beft::hypotheses_t hypotheses(int i) {
  beft::hypotheses_t message{};
  message.utime = i * 100000;
  message.tick = i;
  beft::hypothesis_t hypothesis{};
  hypothesis.object_id = "person_" + std::to_string(i);
  hypothesis.best_category = "person";
  hypothesis.confidence = 0.8125;
  message.hypotheses.push_back(hypothesis);
  message.num_hypotheses = 1;
  return message;
}

std::map<std::string, beft::bb_entry_t> byChannel(const std::vector<beft::bb_entry_t>& entries) {
  std::map<std::string, beft::bb_entry_t> result;
  for (const auto& entry : entries) result[entry.channel] = entry;
  return result;
}

template <typename Message>
Message decodeEntry(const beft::bb_entry_t& entry) {
  Message message;
  EXPECT_EQ(message.decode(entry.data.data(), 0, static_cast<int>(entry.data.size())),
            static_cast<int>(entry.data.size()));
  return message;
}

}  // namespace

TEST(BlackboardProcess, LateClientCatchesUpAndDumpPrintsIt) {
  const std::string url = uniqueUrl(0);
  const std::string log_path = tempPath("blackboard_log");
  ChildProcess blackboard({BEFT_BLACKBOARD_BIN, "--lcm-url", url, "--status-period", "0"}, log_path);
  ASSERT_TRUE(blackboard.started());

  lcm::LCM publisher(url);
  ASSERT_TRUE(publisher.good());
  // Publish only once the blackboard answers, so it hears everything.
  bool answered = false;
  beft::blackboard::fetchSnapshot(publisher, "probe", {"NOTHING"}, 10.0, &answered);
  ASSERT_TRUE(answered) << "the blackboard did not answer; its log:\n" << readFile(log_path);

  for (int i = 1; i <= 5; ++i) {
    const auto state = robotState(i);
    publisher.publish("ROBOT_STATE", &state);
  }
  for (int i = 1; i <= 2; ++i) {
    const auto message = hypotheses(i);
    publisher.publish("HYPOTHESES", &message);
  }
  beft::fire_t fire{};
  fire.expert = "vision";
  publisher.publish("FIRE", &fire);  // control plane: not stored
  beft::geometry_percepts_t geometry{};
  geometry.utime = 700000;
  geometry.tick = 7;
  publisher.publish("GEOMETRY", &geometry);

  // A client that starts now asks for everything. UDP gives no delivery
  // order between sockets, so ask until the last published messages are in.
  lcm::LCM late(url);
  ASSERT_TRUE(late.good());
  std::map<std::string, beft::bb_entry_t> entries;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < give_up) {
    entries = byChannel(beft::blackboard::fetchSnapshot(late, "late_client", {}, 3.0, &answered));
    if (entries.count("GEOMETRY") && entries["ROBOT_STATE"].sequence == 5 && entries["HYPOTHESES"].sequence == 2)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(answered);
  ASSERT_EQ(entries.size(), 3u) << "expected GEOMETRY, HYPOTHESES and ROBOT_STATE (FIRE is not stored)";
  EXPECT_FALSE(entries.count("FIRE"));

  const auto& robot = entries["ROBOT_STATE"];
  EXPECT_EQ(robot.sequence, 5);
  EXPECT_EQ(robot.utime, 500000);
  const auto state = decodeEntry<beft::robot_state_t>(robot);
  EXPECT_DOUBLE_EQ(state.x, 6.25);
  EXPECT_EQ(state.last_command, "goto 5");
  const auto fused = decodeEntry<beft::hypotheses_t>(entries["HYPOTHESES"]);
  ASSERT_EQ(fused.hypotheses.size(), 1u);
  EXPECT_EQ(fused.hypotheses[0].object_id, "person_2");
  EXPECT_EQ(decodeEntry<beft::geometry_percepts_t>(entries["GEOMETRY"]).tick, 7);

  // Asking for named channels gives only those that exist.
  const auto some = byChannel(beft::blackboard::fetchSnapshot(late, "late_client", {"ROBOT_STATE", "MISSING"}, 3.0));
  ASSERT_EQ(some.size(), 1u);
  EXPECT_EQ(some.begin()->first, "ROBOT_STATE");

  // The dump prints every channel with the values published.
  const auto dump = runCommand(std::string("'") + BEFT_BLACKBOARD_DUMP_BIN + "' --lcm-url '" + url + "' --timeout 5");
  EXPECT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_NE(dump.out.find("3 channel(s)"), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("ROBOT_STATE  beft.robot_state_t  seq 5  t 0.5 s"), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("    x: 6.25\n"), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("    y: -3.5\n"), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("last_command: \"goto 5\""), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("HYPOTHESES  beft.hypotheses_t  seq 2"), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("object_id: \"person_2\""), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("confidence: 0.8125"), std::string::npos) << dump.out;
  EXPECT_NE(dump.out.find("GEOMETRY  beft.geometry_percepts_t  seq 1  t 0.7 s"), std::string::npos) << dump.out;
  EXPECT_EQ(dump.out.find("FIRE"), std::string::npos) << dump.out;

  const auto filtered = runCommand(std::string("'") + BEFT_BLACKBOARD_DUMP_BIN + "' --lcm-url '" + url +
                                   "' --timeout 5 --summary --channel HYPOTHESES --channel NOPE");
  EXPECT_EQ(filtered.exit_code, 0) << filtered.err;
  EXPECT_NE(filtered.out.find("HYPOTHESES  beft.hypotheses_t  seq 2"), std::string::npos) << filtered.out;
  EXPECT_NE(filtered.out.find("NOPE  nothing stored"), std::string::npos) << filtered.out;
  EXPECT_EQ(filtered.out.find("ROBOT_STATE"), std::string::npos) << filtered.out;
  EXPECT_EQ(filtered.out.find("object_id"), std::string::npos) << filtered.out;

  EXPECT_EQ(blackboard.stop(), 0);
  const std::string log = readFile(log_path);
  EXPECT_NE(log.find("new channel ROBOT_STATE (beft.robot_state_t)"), std::string::npos) << log;
  EXPECT_NE(log.find("answered query"), std::string::npos) << log;
  EXPECT_NE(log.find("from 'late_client'"), std::string::npos) << log;
  EXPECT_NE(log.find("nothing on MISSING"), std::string::npos) << log;
  std::remove(log_path.c_str());
}

TEST(BlackboardProcess, DumpWithoutABlackboardSaysSoAndExits1) {
  const auto result = runCommand(std::string("'") + BEFT_BLACKBOARD_DUMP_BIN + "' --lcm-url '" + uniqueUrl(1) +
                                 "' --timeout 0.3");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("no blackboard answered"), std::string::npos) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
}

TEST(BlackboardProcess, HelpInterfaceAndBadArguments) {
  const std::string bin = std::string("'") + BEFT_BLACKBOARD_BIN + "'";
  const auto help = runCommand(bin + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--history"), std::string::npos) << help.out;

  const auto interface = runCommand(bin + " --interface");
  EXPECT_EQ(interface.exit_code, 0);
  EXPECT_NE(interface.out.find("BB_QUERY  (beft.bb_query_t)"), std::string::npos) << interface.out;
  EXPECT_NE(interface.out.find("BB_SNAPSHOT_<requester>  (beft.bb_snapshot_t"), std::string::npos) << interface.out;

  const auto bad_pattern = runCommand(bin + " --lcm-url '" + uniqueUrl(2) + "' --exclude 'CAMERA_[('");
  EXPECT_NE(bad_pattern.exit_code, 0);
  EXPECT_NE(bad_pattern.err.find("CAMERA_[("), std::string::npos) << bad_pattern.err;

  const auto bad_history = runCommand(bin + " --history 0");
  EXPECT_NE(bad_history.exit_code, 0);
  EXPECT_NE(bad_history.err.find("--history"), std::string::npos) << bad_history.err;

  const auto dump_help = runCommand(std::string("'") + BEFT_BLACKBOARD_DUMP_BIN + "' --help");
  EXPECT_EQ(dump_help.exit_code, 0);
  EXPECT_NE(dump_help.out.find("--channel"), std::string::npos) << dump_help.out;
}
