// The run recorder: in-process on memq (order, content, exclusions, refusals),
// then beft-record as a process stopped right after a burst of messages.
#include "services/record/recorded_ports.hpp"
#include "services/record/recorder.hpp"
#include "services/record/timestamp_order.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include "lib/launch/free_port.hpp"
#include "lib/common/lcm_url.hpp"

extern char** environ;

namespace {

struct Recorded {
  std::string channel;
  std::string data;
};

std::vector<Recorded> readLog(const std::string& path) {
  std::vector<Recorded> events;
  lcm::LogFile log(path, "r");
  EXPECT_TRUE(log.good()) << path;
  if (!log.good()) return events;
  while (const lcm::LogEvent* event = log.readNextEvent())
    events.push_back({event->channel, std::string(static_cast<const char*>(event->data), event->datalen)});
  return events;
}

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("beft_test_record_" + std::to_string(getpid()) + "_" + name))
      .string();
}

std::string payload(int i, std::size_t size = 16) {
  std::string data = "message " + std::to_string(i) + " ";
  data.resize(std::max(size, data.size()), static_cast<char>('a' + i % 26));
  return data;
}

TEST(Recorder, WritesEveryMessageInOrderAndLeavesOutExcludedChannels) {
  const std::string path = tempPath("memq.lcmlog");
  std::filesystem::remove(path);
  {
    lcm::LCM lcm("memq://");
    beft::record::RecordOptions options;
    options.path = path;
    options.exclude_regex = "HEARTBEAT|FIRE";
    beft::record::Recorder recorder(lcm, "memq://", options, beft::record::RecordedPorts().taken());
    for (int i = 0; i < 200; ++i) {
      const std::string data = payload(i, i % 50 == 0 ? 60000 : 16);
      lcm.publish(i % 3 == 0 ? "A" : i % 3 == 1 ? "HEARTBEAT" : "B_LONGER_NAME", data.data(),
                  static_cast<unsigned>(data.size()));
    }
    recorder.drain(10, 2000);
    EXPECT_EQ(recorder.events(), 133);  // 200 less the 67 HEARTBEATs
  }
  const auto events = readLog(path);
  ASSERT_EQ(events.size(), 133u);
  int expected = 0;
  for (const auto& event : events) {
    while (expected % 3 == 1) ++expected;  // HEARTBEAT: excluded
    EXPECT_EQ(event.channel, expected % 3 == 0 ? "A" : "B_LONGER_NAME");
    EXPECT_EQ(event.data, payload(expected, expected % 50 == 0 ? 60000 : 16));
    ++expected;
  }
  std::filesystem::remove(path);
}

TEST(TimestampOrder, WritesOldestFirstAndHoldsBackTheLastMillisecond) {
  beft::record::TimestampOrder order(1000);
  // As a recorder may read them: an answer queued before what caused it.
  order.add({"FIRE", {1}, 9400});
  order.add({"DONE", {2}, 9300});
  order.add({"A", {3}, 5000});
  order.add({"B", {4}, 5000});  // the same time: arrival order
  std::vector<std::string> written;
  const auto write = [&written](const beft::record::TimedEvent& e) { written.push_back(e.channel); };
  EXPECT_EQ(order.release(10000, write), 2u);  // 9300 and 9400 are within a millisecond of now
  EXPECT_EQ(written, (std::vector<std::string>{"A", "B"}));
  EXPECT_EQ(order.held(), 2u);
  order.add({"LATE", {5}, 9350});  // raced the FIRE and came with the next read
  EXPECT_EQ(order.release(10600, write), 3u);
  EXPECT_EQ(written, (std::vector<std::string>{"A", "B", "DONE", "LATE", "FIRE"}));
  order.add({"LAST", {6}, 10500});
  EXPECT_EQ(order.release(10600, write), 0u);
  EXPECT_EQ(order.releaseAll(write), 1u);
  EXPECT_EQ(written.back(), "LAST");
  EXPECT_EQ(order.held(), 0u);
}

TEST(Recorder, RefusesToReplaceAFileOrABadPattern) {
  const std::string path = tempPath("exists.lcmlog");
  std::ofstream(path) << "precious";
  lcm::LCM lcm("memq://");
  beft::record::RecordOptions options;
  options.path = path;
  const beft::transport::Selection taken = beft::record::RecordedPorts().taken();
  EXPECT_THROW(beft::record::Recorder(lcm, "memq://", options, taken), std::runtime_error);
  std::stringstream kept;
  kept << std::ifstream(path).rdbuf();
  EXPECT_EQ(kept.str(), "precious");
  options.overwrite = true;
  options.exclude_regex = "(unclosed";
  EXPECT_THROW(beft::record::Recorder(lcm, "memq://", options, taken), std::runtime_error);
  options.exclude_regex.clear();
  options.path = tempPath("no/such/folder/x.lcmlog");
  EXPECT_THROW(beft::record::Recorder(lcm, "memq://", options, taken), std::runtime_error);
  std::filesystem::remove(path);
}

TEST(RecordProcess, KeepsEverySentMessageWhenStoppedRightAfterABurst) {
  const int port = beft::launch::findFreeUdpPort(30000, 34999);
  ASSERT_GT(port, 0);
  const std::string url = beft::lcmUrlForPort(port);
  const std::string path = tempPath("process.lcmlog");
  const std::string err_path = tempPath("process.err");
  std::filesystem::remove(path);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = {BEFT_RECORD_BIN, "--lcm-url", url, path};
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);

  // Ready once it says so (it has subscribed by then).
  auto readErr = [&] {
    std::stringstream text;
    text << std::ifstream(err_path).rdbuf();
    return text.str();
  };
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (readErr().find("recording") == std::string::npos && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_NE(readErr().find("recording"), std::string::npos) << readErr();

  // A tick's worth of traffic several times over: small messages and camera-sized ones.
  lcm::LCM publisher(url);
  const int count = 400;
  for (int i = 0; i < count; ++i) {
    const std::string data = payload(i, i % 20 == 0 ? 57000 : 40);
    publisher.publish(i % 20 == 0 ? "CAMERA" : "SMALL", data.data(), static_cast<unsigned>(data.size()));
    if (i % 40 == 39) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << readErr();
  EXPECT_EQ(WEXITSTATUS(status), 0) << readErr();
  EXPECT_NE(readErr().find("recorded " + std::to_string(count) + " messages"), std::string::npos) << readErr();

  // Every message sent, in order, and the recorder's final account of the log.
  auto events = readLog(path);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back().channel, "RECORD_STATUS");
  events.erase(std::remove_if(events.begin(), events.end(),
                              [](const Recorded& event) { return event.channel == "RECORD_STATUS"; }),
               events.end());
  ASSERT_EQ(events.size(), static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(events[i].channel, i % 20 == 0 ? "CAMERA" : "SMALL");
    EXPECT_EQ(events[i].data, payload(i, i % 20 == 0 ? 57000 : 40)) << "message " << i;
  }
  std::filesystem::remove(path);
  std::filesystem::remove(err_path);
}

}  // namespace
