// Shared by the fuzz targets: the input as a temporary file, for readers
// that take a path.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

namespace beft::fuzz {

class InputFile {
 public:
  InputFile(const uint8_t* data, std::size_t size, const char* suffix) {
    path_ = "/tmp/beft_fuzz_" + std::to_string(getpid()) + suffix;
    if (std::FILE* file = std::fopen(path_.c_str(), "wb")) {
      if (size > 0) std::fwrite(data, 1, size, file);
      std::fclose(file);
    }
  }
  ~InputFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace beft::fuzz
