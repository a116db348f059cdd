// Starting the programs an experiment runs (beft-generate, beft-run), their
// output into a file; they end with the experiment if it is killed.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace beft::experiment {

// Starts argv[0] (a path) with stdout and stderr written to `output_file`;
// its pid, or -1.
pid_t startProgram(const std::vector<std::string>& argv, const std::string& output_file);

// The exit code for a waitpid status (128 + the signal for a killed program).
int exitCodeOf(int status);

// Starts the program and waits for it; its exit code.
int runProgram(const std::vector<std::string>& argv, const std::string& output_file);

}  // namespace beft::experiment
