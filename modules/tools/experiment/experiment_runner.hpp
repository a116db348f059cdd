// beft-experiment from the file to the summary: the scenes generated, the
// episodes not yet done run in the local pool, episodes.csv and the summary
// written and printed.
#pragma once

#include <string>

namespace beft::experiment {

struct RunnerOptions {
  std::string file, out_dir;
  int jobs = 1;
  bool retry_failed = false;
  bool list_only = false;  // --list: say what would run, run nothing
};

// The program's exit code: 0 when every episode is done, 1 when some failed,
// 2 for a bad experiment file, 130 when interrupted.
int runExperiment(const RunnerOptions& options);

}  // namespace beft::experiment
