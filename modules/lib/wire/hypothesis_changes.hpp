// The hypotheses of a tick as a keyframe (HYPOTHESES) and the changes since
// it (HYPOTHESIS_CHANGES, hypothesis_changes_t): the one place that says how
// the two make the whole list, for the fusion expert that writes them, the
// experts that read them and the tools that read a log.
#pragma once

#include <cstdint>

#include <beft/hypotheses_t.hpp>
#include <beft/hypothesis_changes_t.hpp>

namespace beft::wire {

// Whether two hypotheses say the same (every field).
bool sameHypothesis(const hypothesis_t& a, const hypothesis_t& b);

// What `whole` (the hypotheses of its tick) changed or added since `keyframe`;
// utime and tick are whole's. The list only grows (fusion keeps a hypothesis
// for the rest of the run), in order of first perception.
hypothesis_changes_t changesSince(const hypotheses_t& keyframe, const hypotheses_t& whole);

// The whole list of the changes' tick: the keyframe with the changes applied,
// stamped with the changes' utime and tick. False (and `whole` untouched) if
// the changes do not belong to this keyframe or do not add up to
// num_hypotheses.
bool applyChanges(const hypotheses_t& keyframe, const hypothesis_changes_t& changes, hypotheses_t& whole);

}  // namespace beft::wire
