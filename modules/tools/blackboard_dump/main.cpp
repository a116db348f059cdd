// beft-blackboard-dump (./beft blackboard dump): asks a running blackboard
// for its current content and prints each channel's latest message, decoded.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/wire/message_decoder.hpp"
#include "blackboard/snapshot_client.hpp"
#include "lib/common/command_line.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/transport/publisher.hpp"

namespace {

std::string entryHeader(const beft::bb_entry_t& entry) {
  std::string type = beft::blackboard::typeNameOf(entry.data.data(), static_cast<int>(entry.data.size()));
  if (type.empty()) type = "unknown type";
  return entry.channel + "  " + type + "  seq " + std::to_string(entry.sequence) + "  t " +
         beft::blackboard::formatNumber(static_cast<double>(entry.utime) / 1e6) + " s  " +
         std::to_string(entry.data.size()) + " bytes";
}

int dump(const std::string& lcm_url, const std::vector<std::string>& channels, double timeout_s, int max_lines,
         bool summary) {
  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "beft blackboard dump: cannot open LCM at %s\n", lcm_url.c_str());
    return 1;
  }
  const auto publishing = beft::transport::attachPublisher(lcm, lcm_url, "beft-blackboard-dump");
  const std::string requester = "dump_" + std::to_string(getpid());
  const auto start = std::chrono::steady_clock::now();
  const auto snapshot = beft::blackboard::requestSnapshot(lcm, requester, channels, timeout_s);
  if (!snapshot) {
    std::fprintf(stderr,
                 "beft blackboard dump: no blackboard answered on %s within %s s "
                 "(is beft-blackboard running with the same --lcm-url?)\n",
                 lcm_url.c_str(), beft::blackboard::formatNumber(timeout_s).c_str());
    return 1;
  }
  const double latency_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  char latency[32];
  std::snprintf(latency, sizeof latency, "%.1f ms", latency_ms);
  std::printf("blackboard on %s: %d channel(s), answered in %s\n", lcm_url.c_str(), snapshot->num_entries, latency);
  if (summary) std::printf("\n");
  for (const auto& entry : snapshot->entries) {
    if (!summary) std::printf("\n");
    std::printf("%s\n", entryHeader(entry).c_str());
    if (summary) continue;
    beft::blackboard::DescribeOptions options;
    options.max_lines = max_lines;
    for (const auto& line : beft::blackboard::MessageDecoder::beftTypes().describeLines(
             entry.channel, entry.data.data(), static_cast<int>(entry.data.size()), options))
      std::printf("    %s\n", line.c_str());
  }
  for (const auto& channel : channels) {
    bool found = false;
    for (const auto& entry : snapshot->entries) found = found || entry.channel == channel;
    if (found) continue;
    if (!summary) std::printf("\n");
    std::printf("%s  nothing stored\n", channel.c_str());
  }
  return 0;
}

struct Options {
  std::string lcm_url = beft::defaultLcmUrl();
  std::vector<std::string> channels;
  double timeout_s = 2.0;
  int max_lines = 40;
  bool summary = false;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Prints what a running blackboard holds: for each channel its latest message with the message type, "
      "sequence number, utime in seconds and the decoded fields. Exits 1 when no blackboard answers.",
      "beft blackboard dump");
  app.add_option("--lcm-url", o.lcm_url, "LCM URL of the running system (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--channel", o.channels, "only this channel (repeatable); default every channel");
  app.add_option("--timeout", o.timeout_s, "seconds to wait for the blackboard's answer")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-lines", o.max_lines, "lines printed per message; the rest is counted")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_flag("--summary", o.summary, "one line per channel, no fields");
  return beft::parseCommandLine(app, argc, argv);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  try {
    return dump(o.lcm_url, o.channels, o.timeout_s, o.max_lines, o.summary);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "beft blackboard dump: %s\n", error.what());
    return 1;
  }
}
