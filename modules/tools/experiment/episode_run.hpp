// One episode as an ordinary beft-run in OUT/episodes/ID/, and what its folder
// says of it: episode.json, written when beft-run has ended, records whether
// it ran to the end (and its report can be read) or failed, and why.
#pragma once

#include <string>
#include <vector>

#include "tools/experiment/experiment.hpp"

namespace beft::experiment {

inline const char* const kRunOutput = "run.txt";        // beft-run's own output
inline const char* const kEpisodeFile = "episode.json";
inline const char* const kRunLog = "run.lcmlog";        // beft-run's log

enum class Status { missing, done, failed };

struct EpisodeState {
  Status status = Status::missing;
  int exit_code = 0;
  double wall_s = 0;
  double simulated_s = 0;  // of a done episode: its report's sim_time_s
  std::string reason;  // why it failed
  std::vector<std::string> command;  // the run's options as recordedCommand() wrote them
  bool log_removed = false;  // the run log went by the experiment's log policy (log_policy.hpp)
};

std::string episodeFolder(const std::string& out_dir, const Episode& episode);

// beft-run SCENE --out FOLDER with the episode's values as options.
std::vector<std::string> runCommand(const Experiment& experiment, const Episode& episode, const std::string& folder,
                                    const std::string& bin_dir);

// The command as recorded in episode.json: without the program's path, the
// experiment's folder written OUT, so that a moved folder or build still matches.
std::vector<std::string> recordedCommand(const std::vector<std::string>& command, const std::string& out_dir);

// missing unless episode.json is there, and for done, report.json reads too.
EpisodeState readEpisodeState(const std::string& folder);
void writeEpisodeState(const std::string& folder, const EpisodeState& state);

// The state of a finished beft-run: done for exit code 0 and a readable
// report, else failed with the last error it or its processes wrote.
EpisodeState finishedState(const std::string& folder, int exit_code, double wall_s);

}  // namespace beft::experiment
