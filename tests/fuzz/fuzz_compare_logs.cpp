// What beft-diff does with a log, on any bytes: the run read, its data
// messages compared with an empty run's and with themselves, and every
// difference described (decoded). It ends without throwing or crashing.
#include <cstdlib>

#include "lib/compare/data_comparison.hpp"
#include "lib/compare/difference_text.hpp"
#include "lib/compare/run_log.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  beft::fuzz::InputFile file(data, size, ".lcmlog");
  const beft::compare::RunLog run = beft::compare::readRunLog(file.path());
  beft::compare::ComparisonOptions every;
  every.max_differences = 0;
  const auto against_nothing = beft::compare::compareRuns(run.messages, {}, every);
  for (const auto& difference : against_nothing.differences) beft::compare::describeDifference(difference);
  const auto against_itself = beft::compare::compareRuns(run.messages, run.messages, every);
  // A run differs from itself only where the guard refuses a message.
  for (const auto& difference : against_itself.differences)
    if (difference.kind != beft::compare::DifferenceKind::kRefused) std::abort();
  return 0;
}
