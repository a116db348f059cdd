// The lines the run's processes write into the run's folder (the launcher's
// processes.log, lib/launch/supervisor.hpp output_file), followed as it grows,
// for the viewer's /log topic. A file that is not there yet, is cut or
// replaced is followed again from its start.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace beft::bridge {

class LogTail {
 public:
  // Starts `backlog_bytes` before the file's end (at a line's start), so a
  // viewer that comes late sees the last lines too.
  explicit LogTail(std::string path, std::size_t backlog_bytes = 16 * 1024);
  ~LogTail();
  LogTail(const LogTail&) = delete;
  LogTail& operator=(const LogTail&) = delete;

  // The whole lines written since the last call (without their newline), at
  // most `max_lines`; the rest on the next call.
  std::vector<std::string> newLines(std::size_t max_lines = 1000);
  const std::string& path() const { return path_; }

 private:
  bool reopenIfNeeded();

  std::string path_;
  std::size_t backlog_bytes_;
  std::FILE* file_ = nullptr;
  uint64_t inode_ = 0;
  uint64_t offset_ = 0;
  std::string partial_;
  bool first_open_ = true;
};

// A line of processes.log, "[vision] text": the process and its text
// (process "" when the line has no such prefix).
struct ProcessLine {
  std::string process;
  std::string text;
};
ProcessLine splitProcessLine(const std::string& line);

}  // namespace beft::bridge
