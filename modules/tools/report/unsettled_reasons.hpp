// Why a hypothesis was left unsettled, for whoever reads a report whose
// mission did not complete: whether any place the robot could reach sees the
// object at all on the ground truth (lib/scenario/sight_lines.hpp), and what
// the exploration expert said of it when it stopped (its STOP_REQUEST names
// each target it left, "; ID: why").
#pragma once

#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"
#include "lib/scenario/scenario.hpp"

namespace beft::report {

// Fills report.unsettled_why for every id of report.unsettled.
void explainUnsettled(const scenario::Scenario& scenario, RunReport& report);

}  // namespace beft::report
