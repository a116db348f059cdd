#include "tests/system/run_support.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <poll.h>
#include <fcntl.h>
#include <stdexcept>
#include <thread>

#include "lib/common/channels.hpp"
#include "lib/compare/difference_text.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/run_identity.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "lib/wire/message_check.hpp"

namespace beft::system_test {

ProgramResult runCommand(const std::string& command_line, double timeout_s) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    dup2(fds[1], STDOUT_FILENO);
    dup2(fds[1], STDERR_FILENO);
    close(fds[0]);
    close(fds[1]);
    execl("/bin/sh", "sh", "-c", command_line.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  fcntl(fds[0], F_SETFL, O_NONBLOCK);
  ProgramResult result;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  bool exited = false;
  while (!exited) {
    pollfd pfd{fds[0], POLLIN, 0};
    poll(&pfd, 1, 50);
    char buffer[4096];
    ssize_t n;
    while ((n = read(fds[0], buffer, sizeof(buffer))) > 0) result.output.append(buffer, static_cast<std::size_t>(n));
    if (waitpid(pid, &status, WNOHANG) == pid) exited = true;
    else if (std::chrono::steady_clock::now() > deadline) {
      kill(-pid, SIGTERM);
      std::this_thread::sleep_for(std::chrono::seconds(2));
      kill(-pid, SIGKILL);
      waitpid(pid, &status, 0);
      result.output += "\n[test] killed after " + std::to_string(timeout_s) + " s\n";
      exited = true;
    }
  }
  char buffer[4096];
  ssize_t n;
  while ((n = read(fds[0], buffer, sizeof(buffer))) > 0) result.output.append(buffer, static_cast<std::size_t>(n));
  close(fds[0]);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

std::string binDir() { return BEFT_BIN_DIR; }
std::string sourceDir() { return BEFT_SOURCE_DIR; }

std::vector<LoggedMessage> readLog(const std::string& path, uint64_t* other_run_events, const std::string& run_id) {
  const int64_t run = run_id.empty() ? wire::runOfLog(path) : wire::parseRunId(run_id);
  compare::RunLog log = compare::readRunLog(path, run);
  if (other_run_events) *other_run_events = log.other_run_events;
  return std::move(log.messages);
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(in);
}

DataComparison compareDataMessages(const std::vector<LoggedMessage>& expected, const std::vector<LoggedMessage>& actual,
                                   const compare::ComparisonOptions& options) {
  const compare::RunComparison comparison = compare::compareRuns(expected, actual, options);
  DataComparison result;
  result.expected = comparison.first_messages;
  result.actual = comparison.second_messages;
  if (!comparison.identical())
    result.first_difference =
        compare::describeDifference(comparison.differences.front(), compare::DifferenceLabels{"expected", "actual"});
  return result;
}

std::vector<beft::hypotheses_t> hypothesesOfEachTick(const std::vector<LoggedMessage>& log) {
  std::map<int64_t, beft::hypotheses_t> keyframes, whole_of_tick;
  std::vector<beft::hypothesis_changes_t> changes;
  for (const auto& event : log) {
    if (event.channel == channels::kHypotheses) {
      beft::hypotheses_t keyframe{};
      if (wire::guardedDecode(event.data.data(), event.data.size(), keyframe).ok())
        keyframes[keyframe.tick] = std::move(keyframe);
    } else if (event.channel == channels::kHypothesisChanges) {
      beft::hypothesis_changes_t message{};
      if (wire::guardedDecode(event.data.data(), event.data.size(), message).ok()) changes.push_back(std::move(message));
    }
  }
  if (changes.empty()) whole_of_tick = keyframes;  // a log from before the changes
  for (const auto& message : changes) {
    const auto keyframe = keyframes.find(message.keyframe_tick);
    beft::hypotheses_t whole{};
    if (keyframe != keyframes.end() && wire::applyChanges(keyframe->second, message, whole))
      whole_of_tick[whole.tick] = std::move(whole);
  }
  std::vector<beft::hypotheses_t> out;
  for (auto& [tick, whole] : whole_of_tick) out.push_back(std::move(whole));
  return out;
}

std::string lineAfter(const std::string& output, const std::string& prefix) {
  std::size_t pos = 0;
  while (pos < output.size()) {
    const auto end = output.find('\n', pos);
    const std::string line = output.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return "";
}

std::string writeCurbScenario(const std::string& dir) {
  const std::string path = dir + "/curb.xml";
  std::ofstream out(path);
  out << R"(<?xml version="1.0"?>
<scenario name="curb" dt="0.1" duration="150" seed="3">
  <world width="20" height="10"/>
  <robot x="2" y="3" yaw="0"/>
  <object id="caller" label="person" x="15" y="3" activity="yelling">
    <visual shape="cylinder" radius="0.3" height="1.8" color="#d04040"/>
    <acoustic sound=")" << sourceDir() << R"(/scenarios/sounds/help.wav"/>
  </object>
  <object id="curb" label="wall" x="8" y="3.5" yaw="90">
    <visual shape="box" size="7 0.3 0.1" color="#707070"/>
  </object>
</scenario>
)";
  return path;
}

std::vector<Contact> contactsWith(const std::string& processes_log, const std::string& object) {
  const std::regex line(R"(collision at tick (\d+): stopped at contact with object ')" + object +
                        R"(' at \(([-\d.]+), ([-\d.]+)\))");
  std::vector<Contact> contacts;
  for (std::sregex_iterator it(processes_log.begin(), processes_log.end(), line), end; it != end; ++it)
    contacts.push_back({std::stoll((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3])});
  return contacts;
}

}  // namespace beft::system_test
