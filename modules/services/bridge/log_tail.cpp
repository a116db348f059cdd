#include "services/bridge/log_tail.hpp"

#include <sys/stat.h>

#include <utility>

namespace beft::bridge {

LogTail::LogTail(std::string path, std::size_t backlog_bytes) : path_(std::move(path)), backlog_bytes_(backlog_bytes) {}

LogTail::~LogTail() {
  if (file_) std::fclose(file_);
}

bool LogTail::reopenIfNeeded() {
  struct stat on_disk {};
  if (stat(path_.c_str(), &on_disk) != 0) return file_ != nullptr;
  const bool replaced = file_ && static_cast<uint64_t>(on_disk.st_ino) != inode_;
  const bool cut = file_ && static_cast<uint64_t>(on_disk.st_size) < offset_;
  if (file_ && !replaced && !cut) return true;
  if (file_) std::fclose(file_);
  file_ = std::fopen(path_.c_str(), "rb");
  if (!file_) return false;
  inode_ = static_cast<uint64_t>(on_disk.st_ino);
  offset_ = 0;
  partial_.clear();
  const uint64_t size = static_cast<uint64_t>(on_disk.st_size);
  if (first_open_ && size > backlog_bytes_) {
    offset_ = size - backlog_bytes_;
    std::fseek(file_, static_cast<long>(offset_), SEEK_SET);
    for (int c; (c = std::fgetc(file_)) != EOF && c != '\n';) ++offset_;  // to the next line's start
    ++offset_;
  }
  first_open_ = false;
  return true;
}

std::vector<std::string> LogTail::newLines(std::size_t max_lines) {
  std::vector<std::string> lines;
  if (!reopenIfNeeded()) return lines;
  std::fseek(file_, static_cast<long>(offset_), SEEK_SET);
  char buffer[4096];
  while (lines.size() < max_lines && std::fgets(buffer, sizeof buffer, file_)) {
    std::string chunk(buffer);
    offset_ += chunk.size();
    if (chunk.back() != '\n') {
      partial_ += chunk;
      if (partial_.size() > 64 * 1024) {  // a line that never ends is cut, not kept whole
        lines.push_back(std::move(partial_));
        partial_.clear();
      }
      continue;
    }
    chunk.pop_back();
    lines.push_back(partial_ + chunk);
    partial_.clear();
  }
  std::clearerr(file_);
  return lines;
}

ProcessLine splitProcessLine(const std::string& line) {
  if (line.size() > 2 && line[0] == '[') {
    const std::size_t close = line.find(']');
    if (close != std::string::npos && close < 64) {
      const std::size_t text = line.size() > close + 1 && line[close + 1] == ' ' ? close + 2 : close + 1;
      return {line.substr(1, close - 1), line.substr(text)};
    }
  }
  return {"", line};
}

}  // namespace beft::bridge
