// A launch file: the processes of a run (scenarios/launch/*.xml).
//
//   <launch name="mission">
//     <arg name="planner" default="pf"/>
//     <process name="planner" command="beft-planner" args="--planner ${planner}"
//              group="infra" restart="on-failure" max_restarts="3" host="local"/>
//     <process name="arbiter" command="beft-arbiter" args="..." role="arbiter"/>
//   </launch>
//
// ${name} is replaced by an <arg> (its default, or the value given with --set);
// ${lcm_url} is always defined. Every process also gets --lcm-url appended
// unless lcm_url="0".
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace beft::launch {

enum class RestartPolicy { Never, OnFailure };

struct ProcessSpec {
  std::string name;
  std::string command;            // a program in the build's bin/ or on PATH
  std::vector<std::string> args;  // after substitution
  std::string group;              // e.g. infra, sensor, low, mid, high, control
  RestartPolicy restart = RestartPolicy::Never;
  int max_restarts = 3;
  std::string host = "local";     // host label: where this process runs
  bool is_arbiter = false;        // the run ends when it exits
  bool append_lcm_url = true;
  int line = 0;
};

struct LaunchSpec {
  std::string file, name;
  std::map<std::string, std::string> args;  // resolved values
  std::vector<ProcessSpec> processes;       // file order = start order
};

class LaunchError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads and resolves a launch file; overrides set or add <arg> values.
// Throws LaunchError("FILE:LINE: what is wrong").
LaunchSpec loadLaunchFile(const std::string& path, const std::map<std::string, std::string>& overrides);

// Splits an argument string on whitespace, honouring "double" and 'single' quotes.
std::vector<std::string> splitArguments(const std::string& text);

}  // namespace beft::launch
