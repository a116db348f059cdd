// Which Petri net a recorded run was scheduled by: its arbiter names the
// net's file in the run's processes.log ("info: net PATH: 15 places, ..."),
// so that `beft view logs/<run>/` draws the same net for the page.
#pragma once

#include <string>

namespace beft::view {

// The PNML file named in `processes_log`, if that file is still there;
// "" when the log names none or the file is gone.
std::string netOfRun(const std::string& processes_log);

}  // namespace beft::view
