#include "tools/diff/log_diff.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "lib/common/channels.hpp"
#include "lib/compare/data_comparison.hpp"
#include "lib/compare/difference_text.hpp"
#include "lib/compare/run_log.hpp"

namespace beft::diff {
namespace {

// Why `path` cannot be read as a log, or "" if it can be opened.
std::string unreadable(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) return path + ": " + std::strerror(errno);
  if (!S_ISREG(info.st_mode)) return path + ": not a file";
  std::ifstream in(path, std::ios::binary);
  if (!in) return path + ": " + std::strerror(errno);
  return "";
}

// The run of one log, or nothing after saying on `err` why it is no log.
std::optional<compare::RunLog> readLog(const std::string& path, std::FILE* err) {
  if (const std::string why = unreadable(path); !why.empty()) {
    std::fprintf(err, "beft-diff: cannot read %s\n", why.c_str());
    return std::nullopt;
  }
  try {
    compare::RunLog run = compare::readRunLog(path);
    if (run.messages.empty() && run.other_run_events == 0) {
      std::fprintf(err, "beft-diff: %s: not an LCM log: no event in it%s%s\n", path.c_str(),
                   run.damage.any() ? "; " : "", run.damage.summary().c_str());
      return std::nullopt;
    }
    if (run.damage.any()) std::fprintf(err, "beft-diff: warning: %s: %s\n", path.c_str(), run.damage.summary().c_str());
    if (run.other_run_events > 0)
      std::fprintf(err, "beft-diff: %s: %llu events of other runs left out\n", path.c_str(),
                   static_cast<unsigned long long>(run.other_run_events));
    return run;
  } catch (const std::exception& e) {
    std::fprintf(err, "beft-diff: cannot read %s: %s\n", path.c_str(), e.what());
    return std::nullopt;
  }
}

// False after naming on `err` a --channel that is no data channel.
bool dataChannelsOnly(const std::set<std::string>& names, std::FILE* err) {
  for (const auto& name : names) {
    if (channels::isDataPlaneChannel(name)) continue;
    std::string known;
    for (const auto& entry : channels::allChannels())
      if (channels::isDataPlaneChannel(entry.name)) known += std::string(known.empty() ? "" : ", ") + entry.name;
    std::fprintf(err, "beft-diff: --channel %s: not a data channel; the data channels: %s\n", name.c_str(),
                 known.c_str());
    return false;
  }
  return true;
}

}  // namespace

int diffLogs(const DiffOptions& options, std::FILE* out, std::FILE* err) {
  if (!dataChannelsOnly(options.channels, err)) return kBadInput;
  const auto first = readLog(options.first_path, err);
  const auto second = readLog(options.second_path, err);
  if (!first || !second) return kBadInput;
  compare::ComparisonOptions comparison_options;
  comparison_options.channels = options.channels;
  comparison_options.max_differences = options.all ? 0 : 1;
  const auto comparison = compare::compareRuns(first->messages, second->messages, comparison_options);
  std::fprintf(out, "%s: %zu data messages\n%s: %zu data messages\n", options.first_path.c_str(),
               comparison.first_messages, options.second_path.c_str(), comparison.second_messages);
  if (comparison.identical()) {
    std::fprintf(out, "identical: every data message is the same\n");
    return kIdentical;
  }
  compare::DifferenceLabels labels{options.first_path, options.second_path};
  for (const auto& difference : comparison.differences)
    std::fprintf(out, "%s", compare::describeDifference(difference, labels).c_str());
  if (options.all) std::fprintf(out, "%zu differences\n", comparison.differences.size());
  else std::fprintf(out, "different (the first difference in time shown; --all lists every one)\n");
  return kDifferent;
}

}  // namespace beft::diff
