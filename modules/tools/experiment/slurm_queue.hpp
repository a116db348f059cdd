// What beft-experiment asks Slurm: sbatch to submit a job, squeue whether it
// is still in the queue. Their output goes to files in OUT/slurm/.
#pragma once

#include <optional>
#include <string>

namespace beft::experiment {

// The program's path if it is an executable in a folder of PATH, else "".
std::string findOnPath(const std::string& program);

// sbatch --parsable SCRIPT: the job's id, or nullopt with sbatch's error in `error`.
std::optional<std::string> submitJob(const std::string& sbatch, const std::string& script,
                                     const std::string& output_file, std::string& error);

enum class InQueue { yes, no, unknown };  // unknown: squeue failed (the controller unreachable, ...)

// Whether a task of the job is pending, running or completing.
InQueue jobInQueue(const std::string& squeue, const std::string& job_id, const std::string& output_file);

}  // namespace beft::experiment
