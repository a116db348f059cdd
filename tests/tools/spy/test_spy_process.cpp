// beft-spy as a real process on its own UDP port: the table lists the
// channel with its type and count, and --channel prints messages decoded,
// with the size their sender encoded (a BEFT process's envelope left out).
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
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include <beft/robot_state_t.hpp>

#include "lib/common/lcm_url.hpp"
#include "lib/transport/publisher.hpp"

extern char** environ;

namespace {

std::string readFile(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

TEST(SpyProcess, TableAndDecodedMessagesOfAChannel) {
  const int port = 41000 + static_cast<int>(static_cast<unsigned>(getpid()) % 20000u);
  const std::string url = beft::lcmUrlForPort(port);
  const std::string out_path =
      (std::filesystem::temp_directory_path() / ("beft_test_spy_" + std::to_string(getpid()) + ".txt")).string();

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = {BEFT_SPY_BIN, "--lcm-url", url, "--duration", "1.5", "--interval", "0.5",
                                   "--channel", "ROBOT_STATE"};
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);

  // Publish until the spy stops by itself (it was told --duration 1.5):
  // ROBOT_STATE as a BEFT process does, with an envelope; OTHER_CHANNEL as a
  // program outside the project does.
  lcm::LCM publisher(url);
  ASSERT_TRUE(publisher.good());
  beft::robot_state_t state{};
  state.utime = 2500000;
  state.x = 2.5;
  state.last_command = "spy me";
  int status = 0;
  pid_t finished = 0;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while ((finished = waitpid(pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < give_up) {
    beft::transport::publish(publisher, "ROBOT_STATE", state);
    publisher.publish("OTHER_CHANNEL", &state);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (finished == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    FAIL() << "beft-spy did not stop after --duration";
  }
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);

  const std::string out = readFile(out_path);
  std::remove(out_path.c_str());
  const std::string size = std::to_string(state.getEncodedSize()) + " B";
  EXPECT_NE(out.find("ROBOT_STATE  beft.robot_state_t  " + size + "  utime 2.5 s\n"), std::string::npos) << out;
  EXPECT_NE(out.find("    x: 2.5\n"), std::string::npos) << out;
  EXPECT_NE(out.find("    last_command: \"spy me\"\n"), std::string::npos) << out;
  // OTHER_CHANNEL is counted in the table but not decoded.
  EXPECT_NE(out.find("OTHER_CHANNEL  beft.robot_state_t"), std::string::npos) << out;
  EXPECT_NE(out.find("CHANNEL"), std::string::npos) << out;
  EXPECT_NE(out.find("2 channel(s)"), std::string::npos) << out;
  EXPECT_EQ(out.find("OTHER_CHANNEL  beft.robot_state_t  " + size), std::string::npos) << out;
  EXPECT_EQ(out.find("LCM_SELF_TEST"), std::string::npos) << out;
}
