// Which episodes keep their run log (run.lcmlog: hundreds of MB for a
// binaural district, tens of GB for an experiment). By default only those
// that did not succeed (failed, not completed, or with a collision) keep it,
// for a person to replay: a lockstep run is fixed by its scene and seed, so a
// successful episode's command (in its episode.json) makes the same data
// messages again whenever its log is wanted.
#pragma once

#include <optional>
#include <string>

#include "tools/experiment/episode_run.hpp"

namespace beft::experiment {

enum class KeepLogs { unsuccessful, all };

std::optional<KeepLogs> keepLogsNamed(const std::string& name);
std::string nameOf(KeepLogs keep);

// Done, completed and without a collision, by its report.json.
bool succeeded(const std::string& folder, const EpisodeState& state);

// Removes the finished episode's run log if the policy says so; true when it did.
bool applyLogPolicy(const std::string& folder, const EpisodeState& state, KeepLogs keep);

}  // namespace beft::experiment
