// beft-diff: are two runs the same? Their logs compared message by message.
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include "lib/common/command_line.hpp"
#include "tools/diff/log_diff.hpp"

int main(int argc, char** argv) {
  beft::diff::DiffOptions options;
  std::vector<std::string> channels;
  CLI::App app{
      "beft-diff: compares the data messages (world, experts, task stack) of two runs' LCM logs, every "
      "message of every data channel both ways, in order: a message only one log has, a message whose bytes "
      "differ and a message the message guard refuses are differences. The run id in channel names "
      "(VISION@1f3a...) is left out, so two runs' logs compare. Prints the first difference in time, named "
      "(channel, index in the channel, tick) with both messages decoded.\n"
      "Exit: 0 identical, 1 different, 2 bad input (a file missing, unreadable or no LCM log).",
      "beft-diff"};
  app.add_option("first", options.first_path, "the first run's log (A.lcmlog)")->required();
  app.add_option("second", options.second_path, "the second run's log (B.lcmlog)")->required();
  app.add_option("--channel", channels, "compare only this data channel (repeatable)");
  app.add_flag("--all", options.all, "list every difference, not only the first");
  if (const auto code = beft::parseCommandLine(app, argc, argv))
    return *code == 0 ? 0 : beft::diff::kBadInput;
  options.channels.insert(channels.begin(), channels.end());
  return beft::diff::diffLogs(options, stdout, stderr);
}
