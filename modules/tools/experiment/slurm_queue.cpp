#include "tools/experiment/slurm_queue.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tools/experiment/child_process.hpp"
#include "tools/experiment/scenes.hpp"

namespace beft::experiment {
namespace fs = std::filesystem;

std::string findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const fs::path candidate = fs::path(folder.empty() ? "." : folder) / program;
    if (access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate.string();
  }
  return "";
}

std::optional<std::string> submitJob(const std::string& sbatch, const std::string& script,
                                     const std::string& output_file, std::string& error) {
  const int code = runProgram({sbatch, "--parsable", script}, output_file);
  // --parsable prints "ID" or "ID;CLUSTER" (warnings may come before it).
  const std::string last = lastLineOf(output_file);
  const std::string id = last.substr(0, last.find(';'));
  if (code == 0 && !id.empty() && id.find_first_not_of("0123456789") == std::string::npos) return id;
  error = lastLineOf(output_file, "error");
  if (error.empty()) error = last.empty() ? "sbatch exited with code " + std::to_string(code) : last;
  return std::nullopt;
}

InQueue jobInQueue(const std::string& squeue, const std::string& job_id, const std::string& output_file) {
  const int code = runProgram({squeue, "--noheader", "--jobs", job_id, "--format", "%i"}, output_file);
  if (code == 0) return lastLineOf(output_file).empty() ? InQueue::no : InQueue::yes;
  // A job that ended long ago is unknown to the controller.
  return lastLineOf(output_file, "Invalid job id").empty() ? InQueue::unknown : InQueue::no;
}

}  // namespace beft::experiment
