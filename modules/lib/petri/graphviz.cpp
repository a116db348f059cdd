#include "lib/petri/graphviz.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

extern char** environ;

namespace beft::arbiter {

namespace {

// A scratch file holding `text`; "" when it cannot be made.
std::string scratchFileWith(const std::string& text) {
  char scratch[] = "/tmp/beft_net_XXXXXX.dot";
  const int fd = mkstemps(scratch, 4);
  if (fd < 0) return "";
  const bool written = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  close(fd);
  if (!written) {
    unlink(scratch);
    return "";
  }
  return scratch;
}

}  // namespace

std::string runGraphviz(const std::string& graph, const std::string& format, const std::string& out_path) {
  const std::string scratch = scratchFileWith(graph);
  if (scratch.empty()) return "cannot write a scratch file";
  const std::string type = "-T" + format;
  const char* argv[] = {"dot", type.c_str(), "-o", out_path.c_str(), scratch.c_str(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "dot", nullptr, nullptr, const_cast<char* const*>(argv), environ);
  int status = 0;
  if (spawned == 0) waitpid(pid, &status, 0);
  unlink(scratch.c_str());
  if (spawned != 0) return "Graphviz's dot is not installed (./beft setup installs it: apt-get install graphviz)";
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    unlink(out_path.c_str());
    return "dot failed (see above)";
  }
  return "";
}

std::string drawWithGraphviz(const std::string& graph, const std::string& format, std::string& why) {
  char drawing[] = "/tmp/beft_net_XXXXXX.out";
  const int fd = mkstemps(drawing, 4);
  if (fd < 0) {
    why = "cannot create a scratch file";
    return "";
  }
  close(fd);
  why = runGraphviz(graph, format, drawing);
  std::ostringstream bytes;
  if (why.empty()) bytes << std::ifstream(drawing, std::ios::binary).rdbuf();
  unlink(drawing);
  return bytes.str();
}

}  // namespace beft::arbiter
