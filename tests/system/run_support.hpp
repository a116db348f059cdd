// Support for the system tests: run programs, read a run's log and report.
#pragma once

#include <lcm/lcm-cpp.hpp>
#include <beft/hypotheses_t.hpp>
#include <nlohmann/json.hpp>

#include "lib/compare/data_comparison.hpp"
#include "lib/compare/message_filters.hpp"
#include "lib/compare/run_log.hpp"
#include "tests/system/run_folders.hpp"

#include <map>
#include <string>
#include <vector>

namespace beft::system_test {

struct ProgramResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs a command line through sh, capturing its output; kills it after timeout_s.
ProgramResult runCommand(const std::string& command_line, double timeout_s);

std::string binDir();     // build/bin
std::string sourceDir();  // the repository root

using LoggedMessage = compare::LoggedMessage;  // channel (plain name), timestamp [us], data

// Every event of an LCM log file of one run, in order, under plain channel
// names; other runs' events are counted. The run: `run_id` (hex, as beft run
// prints it) or, when empty, the arbiter's of the first FIRE in the log.
std::vector<LoggedMessage> readLog(const std::string& path, uint64_t* other_run_events = nullptr,
                                   const std::string& run_id = "");

template <typename Message>
std::vector<Message> messagesOn(const std::vector<LoggedMessage>& log, const std::string& channel) {
  std::vector<Message> out;
  for (const auto& event : log) {
    if (event.channel != channel) continue;
    Message message;
    if (message.decode(event.data.data(), 0, static_cast<int>(event.data.size())) ==
        static_cast<int>(event.data.size()))
      out.push_back(message);
  }
  return out;
}

nlohmann::json readJson(const std::string& path);

// Two runs compared by their data messages (lib/compare/data_comparison.hpp):
// every message of every data channel of both, in order, both ways; a
// missing, extra or refused message is a difference.
struct DataComparison {
  std::size_t expected = 0, actual = 0;  // data messages of each run
  std::string first_difference;          // the earliest difference, named and decoded; "" when identical
  bool identical() const { return first_difference.empty(); }
};
DataComparison compareDataMessages(const std::vector<LoggedMessage>& expected, const std::vector<LoggedMessage>& actual,
                                   const compare::ComparisonOptions& options = {});

// What a comparison may leave out of a run: refused (injected) messages and
// a restarted process's exact repeats (lib/compare/message_filters.hpp).
using compare::withoutRefused;
using compare::withoutRepeats;

// The whole list of hypotheses of every tick the log has one for, in tick
// order: the HYPOTHESES keyframes with each tick's HYPOTHESIS_CHANGES applied
// (a log from before the changes: its HYPOTHESES as they are).
std::vector<beft::hypotheses_t> hypothesesOfEachTick(const std::vector<LoggedMessage>& log);

// The first line of `output` that starts with `prefix`, without it; "" if none.
std::string lineAfter(const std::string& output, const std::string& prefix);

// Writes dir/curb.xml and returns its path: a curb 0.1 m high (below the
// vision expert's 0.15 m obstacle height: the camera sees floor there) lies
// across the way to a calling person, with a gap at its north end, so the
// robot drives into it unaware (first at tick 110).
std::string writeCurbScenario(const std::string& dir);

// Where a run's processes said the robot touched `object`, in order:
// "collision at tick T: stopped at contact with object 'ID' at (X, Y) ...".
struct Contact {
  int64_t tick = 0;
  double x = 0, y = 0;
};
std::vector<Contact> contactsWith(const std::string& processes_log, const std::string& object);

}  // namespace beft::system_test
