#include "tests/system/run_support.hpp"

#include "lib/wire/obstacle_map_changes.hpp"
#include "lib/wire/obstacle_map_codec.hpp"

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

#include <beft/camera_frame_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/camera/frame_decoding.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/message_check.hpp"
#include "lib/wire/run_identity.hpp"

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

std::string makeTempDir(const std::string& tag) {
  std::string pattern = "/tmp/beft_" + tag + "_XXXXXX";
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  return pattern;
}

std::vector<LoggedMessage> readLog(const std::string& path, uint64_t* other_run_events, const std::string& run_id) {
  const int64_t run = run_id.empty() ? wire::runOfLog(path) : wire::parseRunId(run_id);
  wire::LogReader log(path);
  std::vector<LoggedMessage> events;
  wire::LogEvent event;
  while (log.nextOfRun(event, run)) events.push_back({event.channel, event.timestamp, event.data});
  if (other_run_events) *other_run_events = log.otherRunEvents();
  return events;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(in);
}

std::map<DataKey, std::vector<uint8_t>> dataMessages(const std::vector<LoggedMessage>& log) {
  std::map<DataKey, std::vector<uint8_t>> messages;
  std::map<std::pair<std::string, int64_t>, int> count;
  for (const auto& event : log) {
    if (!channels::isDataPlaneChannel(event.channel) || event.data.size() < 16) continue;
    // What a process of the run would refuse (injected damage) is no message of the run.
    if (!wire::MessageRules::beftTypes().checkForChannel(event.channel, event.data.data(), event.data.size()).ok())
      continue;
    int64_t utime = 0;  // the first field after the 8-byte fingerprint, big-endian
    for (int i = 8; i < 16; ++i) utime = (utime << 8) | event.data[i];
    const int order = count[{event.channel, utime}]++;
    messages[{event.channel, utime, order}] = event.data;
  }
  return messages;
}

DataComparison compareDataMessages(const std::vector<LoggedMessage>& expected_log,
                                   const std::vector<LoggedMessage>& actual_log) {
  const auto expected = dataMessages(expected_log);
  const auto actual = dataMessages(actual_log);
  DataComparison result;
  result.expected = expected.size();
  for (const auto& [key, data] : expected) {
    const auto it = actual.find(key);
    if (it == actual.end()) continue;
    ++result.compared;
    if (it->second == data) continue;
    if (++result.differing == 1)
      result.first_difference = std::get<0>(key) + " at t = " + std::to_string(std::get<1>(key) * 1e-6) + " s";
  }
  return result;
}

namespace {

// A camera frame as its pixels: what the digest pins is the image, not how
// zstd (whose version may change its bytes) packed it.
std::vector<uint8_t> unpackedFrame(const std::vector<uint8_t>& data) {
  beft::camera_frame_t frame{};
  if (!wire::guardedDecode(data.data(), data.size(), frame).ok() || !camera::decodeCameraFrame(frame)) return data;
  std::vector<uint8_t> bytes(frame.getEncodedSize());
  frame.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// An obstacle map as its cells, for the same reason (RLE_ZSTD).
std::vector<uint8_t> unpackedMap(const std::vector<uint8_t>& data) {
  beft::obstacle_map_t map{};
  if (!wire::guardedDecode(data.data(), data.size(), map).ok()) return data;
  try {
    map.data = planners::makeObstacleMap(planners::decodeObstacleMap(map), beft::obstacle_map_t::ENCODING_RAW).data;
  } catch (const planners::ObstacleMapError&) {
    return data;
  }
  map.data_size = static_cast<int32_t>(map.data.size());
  map.encoding = beft::obstacle_map_t::ENCODING_RAW;
  std::vector<uint8_t> bytes(map.getEncodedSize());
  map.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace

std::map<std::string, ChannelDigest> dataDigests(const std::vector<LoggedMessage>& log) {
  const auto messages = dataMessages(log);
  // With HYPOTHESIS_CHANGES, HYPOTHESES stands for the whole list of every
  // tick, made from the keyframes and the changes: what it was when the
  // whole list went out every tick.
  // Likewise OBSTACLE_MAP with OBSTACLE_MAP_CHANGES: the map of every tick.
  bool changes_sent = false, map_changes_sent = false;
  for (const auto& [key, data] : messages) {
    if (std::get<0>(key) == channels::kHypothesisChanges) changes_sent = true;
    if (std::get<0>(key) == channels::kObstacleMapChanges) map_changes_sent = true;
  }
  std::map<std::string, ChannelDigest> digests;
  auto add = [&digests](const std::string& channel, const std::vector<uint8_t>& bytes) {
    ChannelDigest& digest = digests[channel];
    ++digest.count;
    for (const uint8_t byte : bytes) digest.hash = (digest.hash ^ byte) * 1099511628211ull;  // FNV-1a prime
  };
  for (const auto& [key, data] : messages) {
    const std::string& channel = std::get<0>(key);
    if (changes_sent && channel == channels::kHypotheses) continue;
    if (map_changes_sent && channel == channels::kObstacleMap) continue;
    const std::string type = channels::typeOfChannel(channel);
    if (type == lcmTypeName<beft::camera_frame_t>()) add(channel, unpackedFrame(data));
    else if (type == lcmTypeName<beft::obstacle_map_t>()) add(channel, unpackedMap(data));
    else add(channel, data);
  }
  if (map_changes_sent) {
    std::map<int64_t, beft::obstacle_map_t> keyframes;
    std::map<int64_t, beft::obstacle_map_changes_t> changes_of_tick;
    for (const auto& [key, data] : messages) {
      if (std::get<0>(key) == channels::kObstacleMap) {
        beft::obstacle_map_t keyframe{};
        if (wire::guardedDecode(data.data(), data.size(), keyframe).ok()) keyframes[keyframe.tick] = keyframe;
      } else if (std::get<0>(key) == channels::kObstacleMapChanges) {
        beft::obstacle_map_changes_t changes{};
        if (wire::guardedDecode(data.data(), data.size(), changes).ok()) changes_of_tick[changes.tick] = changes;
      }
    }
    planners::ObstacleMapAssembler assembler;
    for (const auto& [tick, changes] : changes_of_tick) {
      const auto keyframe = keyframes.find(changes.keyframe_tick);
      if (keyframe == keyframes.end()) continue;
      beft::obstacle_map_t whole = keyframe->second;  // as a map of every tick was sent: raw, its tick's time
      try {
        whole.data = assembler.mapOf(keyframe->second, &changes)->cells;
      } catch (const planners::ObstacleMapError&) {
        continue;
      }
      whole.utime = changes.utime;
      whole.tick = changes.tick;
      whole.encoding = beft::obstacle_map_t::ENCODING_RAW;
      whole.data_size = static_cast<int32_t>(whole.data.size());
      std::vector<uint8_t> bytes(whole.getEncodedSize());
      whole.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
      add(channels::kObstacleMap.name, bytes);
    }
  }
  if (changes_sent) {
    for (const auto& whole : hypothesesOfEachTick(log)) {
      std::vector<uint8_t> bytes(whole.getEncodedSize());
      whole.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
      add(channels::kHypotheses.name, bytes);
    }
  }
  return digests;
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
