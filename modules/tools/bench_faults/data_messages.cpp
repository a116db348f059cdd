#include "tools/bench_faults/data_messages.hpp"

#include "lib/compare/data_comparison.hpp"
#include "lib/compare/difference_text.hpp"
#include "lib/compare/message_filters.hpp"

namespace beft::bench {

std::vector<compare::LoggedMessage> dataMessages(const std::string& log_path, int64_t run_id) {
  return compare::readRunLog(log_path, run_id != 0 ? std::optional<int64_t>(run_id) : std::nullopt).messages;
}

std::string compareRuns(const std::vector<compare::LoggedMessage>& clean, const std::string& log_path,
                        int64_t run_id) {
  std::size_t refused = 0;
  const auto run = compare::withoutRefused(dataMessages(log_path, run_id), refused);
  const compare::RunComparison comparison = compare::compareRuns(clean, run);
  std::string verdict = comparison.identical()
                            ? "yes"
                            : "no: " + compare::summarizeDifference(comparison.differences.front(),
                                                                    {"clean", "this run"});
  if (refused > 0) verdict += " (" + std::to_string(refused) + " refused left out)";
  return verdict;
}

}  // namespace beft::bench
