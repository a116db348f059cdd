#include "tools/experiment/slurm_script.hpp"

#include <cctype>
#include <sstream>

namespace beft::experiment {

std::string shellQuoted(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

namespace {

// The job's name in squeue: the experiment's, only letters, digits and ._-
std::string jobName(const std::string& name) {
  std::string result = "beft-" + name;
  for (char& c : result)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return result;
}

// #SBATCH lines: sbatch reads them without a shell, but takes a value in double quotes.
void writeDirectives(std::ostream& out, const BatchJob& job, const SlurmLimits& limits) {
  out << "#SBATCH --job-name=" << jobName(job.name) << "\n"
      << "#SBATCH --array=0-" << job.ids.size() - 1 << "\n"
      << "#SBATCH --chdir=\"" << job.work_dir << "\"\n"
      << "#SBATCH --output=slurm/task-%A_%a.txt\n"
      << "#SBATCH --cpus-per-task=" << limits.cpus_per_task << "\n";
  if (!limits.partition.empty()) out << "#SBATCH --partition=" << limits.partition << "\n";
  if (limits.time_limit_min > 0) out << "#SBATCH --time=" << limits.time_limit_min << "\n";
  if (limits.mem_mb > 0) out << "#SBATCH --mem=" << limits.mem_mb << "M\n";
}

}  // namespace

std::string batchScript(const BatchJob& job, const SlurmLimits& limits) {
  std::ostringstream out;
  out << "#!/bin/bash\n# The missing episodes of the experiment " << job.name
      << ", one per task of the array (written by beft-experiment --slurm).\n";
  writeDirectives(out, job, limits);
  out << "ids=(\n";
  for (const auto& id : job.ids) out << "  " << shellQuoted(id) << "\n";
  out << ")\nexec";
  for (const auto& arg : job.task_command) out << " " << shellQuoted(arg);
  out << " \"${ids[$SLURM_ARRAY_TASK_ID]}\"\n";
  return out.str();
}

}  // namespace beft::experiment
