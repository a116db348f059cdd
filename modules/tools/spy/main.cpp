// beft-spy (./beft spy): live view of the bus. A table of every channel
// (type, count, rate, size, latest utime) each interval and, for the channels
// named with --channel, every message decoded.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/command_line.hpp"
#include "blackboard/channel_filter.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/message_decoder.hpp"
#include "lib/wire/message_check.hpp"
#include "blackboard/store.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/transport/publisher.hpp"
#include "tools/spy/traffic_table.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
void onSignal(int) { g_stop = 1; }

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

class Spy {
 public:
  Spy(Clock::time_point start, double window_s, std::set<std::string> decoded, int max_lines)
      : start_(start), table_(0.0, window_s), decoded_(std::move(decoded)), max_lines_(max_lines) {}

  // For LCM's subscribeFunction: the member-pointer subscribe crashes under
  // GCC's -fsanitize=vptr (see the top-level CMakeLists).
  static void onMessageOf(const lcm::ReceiveBuffer* buffer, const std::string& channel, Spy* self) {
    self->onMessage(buffer, channel);
  }

  void onMessage(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    if (beft::blackboard::isLcmInternalChannel(channel)) return;
    try {
      // The message as its sender encoded it: the transport's envelope left out.
      const std::size_t payload = beft::wire::payloadSize(static_cast<const uint8_t*>(buffer->data), buffer->data_size);
      const int size = static_cast<int>(payload);
      std::string type = beft::blackboard::typeNameOf(buffer->data, size);
      if (type.empty()) type = "unknown type";
      // What a process of the run would refuse is shown as such, never decoded.
      const beft::wire::Verdict verdict =
          beft::wire::MessageRules::beftTypes().checkForChannel(channel, buffer->data, payload);
      if (!verdict.ok()) type = "refused (" + verdict.text() + ")";
      table_.record(channel, type, payload, secondsSince(start_), beft::blackboard::encodedUtime(buffer->data, size));
      if (!decoded_.count(channel)) return;
      std::string text = channel + "  " + type + "  " + beft::spy::formatBytes(size);
      if (const auto utime = beft::blackboard::encodedUtime(buffer->data, size))
        text += "  utime " + beft::blackboard::formatNumber(static_cast<double>(*utime) / 1e6) + " s";
      text += "\n";
      if (!verdict.ok()) {
        std::fputs(text.c_str(), stdout);
        return;
      }
      beft::blackboard::DescribeOptions options;
      options.max_lines = max_lines_;
      for (const auto& line :
           beft::blackboard::MessageDecoder::beftTypes().describeLines(channel, buffer->data, size, options))
        text += "    " + line + "\n";
      std::fputs(text.c_str(), stdout);
      std::fflush(stdout);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "beft spy: cannot show a message on %s: %s\n", channel.c_str(), error.what());
    }
  }

  void printTable(bool redraw) {
    const double now = secondsSince(start_);
    std::string text;
    if (redraw)
      text = "\033[H\033[2J";  // home and clear: the table stays in place on a terminal
    else
      text = "\n";
    char heading[64];
    std::snprintf(heading, sizeof heading, "--- beft spy, %.1f s ---\n", now);
    text += heading + table_.format(now);
    std::fputs(text.c_str(), stdout);
    std::fflush(stdout);
  }

 private:
  Clock::time_point start_;
  beft::spy::TrafficTable table_;
  std::set<std::string> decoded_;
  int max_lines_;
};

struct Options {
  std::string lcm_url = beft::defaultLcmUrl();
  std::vector<std::string> decoded_channels;
  std::string match = ".*";
  double duration_s = 0;
  double interval_s = 1.0;
  double window_s = 2.0;
  int max_lines = 40;
  int queue_capacity = 2000;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Live view of the channels on the bus: each interval a table with every channel's message type, "
      "message count, rate, size and latest utime; with --channel, every message on that channel decoded "
      "field by field. On a terminal without --channel the table redraws in place; otherwise (piped, or "
      "with --channel) each table is appended.",
      "beft spy");
  app.add_option("--lcm-url", o.lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--channel", o.decoded_channels, "print every message on this channel decoded (repeatable)");
  app.add_option("--match", o.match, "only channels matching this regular expression (LCM subscription)")
      ->capture_default_str();
  app.add_option("--duration", o.duration_s, "stop after this many seconds, 0 = at Ctrl-C")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--interval", o.interval_s, "seconds between tables")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--window", o.window_s, "seconds the rates are measured over")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-lines", o.max_lines, "lines printed per decoded message")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--queue", o.queue_capacity, "LCM queue capacity of the subscription [messages]")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;

}

// Tables every interval, until the duration or a signal; false if LCM failed.
bool watch(const Options& o, lcm::LCM& lcm, Spy& spy, Clock::time_point start) {
  const bool redraw = o.decoded_channels.empty() && isatty(STDOUT_FILENO);
  const auto interval = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.interval_s));
  const auto end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.duration_s));
  auto next_table = start + interval;
  while (!g_stop) {
    const auto now = Clock::now();
    if (o.duration_s > 0 && now >= end) break;
    if (now >= next_table) {
      spy.printTable(redraw);
      next_table += interval;
      if (next_table < now) next_table = now + interval;
    }
    auto wake = next_table;
    if (o.duration_s > 0 && end < wake) wake = end;
    const int wait_ms = static_cast<int>(
        std::max<int64_t>(1, std::chrono::duration_cast<std::chrono::milliseconds>(wake - now).count()));
    if (lcm.handleTimeout(wait_ms) < 0) {
      if (g_stop) break;  // a signal interrupted the wait
      std::fprintf(stderr, "beft spy: LCM failed while waiting for messages\n");
      return false;
    }
  }
  return true;
}

int spyOn(const Options& o) {
  lcm::LCM lcm(o.lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "beft spy: cannot open LCM at %s\n", o.lcm_url.c_str());
    return 1;
  }
  std::unique_ptr<beft::transport::PublisherScope> publishing;  // beside every LCM instance, though the spy only listens
  try {
    publishing = beft::transport::attachPublisher(lcm, o.lcm_url, "beft-spy");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "beft spy: cannot publish on %s: %s\n", o.lcm_url.c_str(), error.what());
    return 1;
  }
  const auto start = Clock::now();
  Spy spy(start, o.window_s, std::set<std::string>(o.decoded_channels.begin(), o.decoded_channels.end()), o.max_lines);
  lcm::Subscription* subscription = lcm.subscribeFunction(o.match, &Spy::onMessageOf, &spy);
  if (!subscription) {
    std::fprintf(stderr, "beft spy: cannot subscribe to '%s'\n", o.match.c_str());
    return 1;
  }
  // Handling is cheap (a count) except for decoded channels; a burst of a
  // tick's messages must not be dropped by the default queue of 30.
  subscription->setQueueCapacity(o.queue_capacity);
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  if (!watch(o, lcm, spy, start)) return 1;
  spy.printTable(false);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (const auto code = parseOptions(argc, argv, options)) return *code;
  return spyOn(options);
}
