#include "lib/common/own_bin_dir.hpp"

#include <unistd.h>

#include <climits>

namespace beft {

std::string ownBinDir() {
  char path[PATH_MAX] = {0};
  const ssize_t n = readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (n <= 0) return ".";
  const std::string exe(path, static_cast<std::size_t>(n));
  return exe.substr(0, exe.rfind('/'));
}

}  // namespace beft
