#include "lib/common/whole_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace beft {

std::string partialPathFor(const std::string& path) {
  const std::filesystem::path target(path);
  const std::string name = "." + target.stem().string() + ".partial-" + std::to_string(getpid()) +
                           target.extension().string();
  return (target.parent_path() / name).string();
}

void commitPartial(const std::string& partial, const std::string& path) {
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(partial.c_str());
    throw std::runtime_error(path + ": cannot write: " + why);
  }
}

void writeWholeFile(const std::string& path, const std::string& bytes) {
  const std::string partial = partialPathFor(path);
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out << bytes;
    if (!out.flush()) {
      std::remove(partial.c_str());
      throw std::runtime_error(path + ": cannot write");
    }
  }
  commitPartial(partial, path);
}

}  // namespace beft
