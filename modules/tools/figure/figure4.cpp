#include "tools/figure/figure4.hpp"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "lib/common/whole_file.hpp"

namespace beft::figure {

namespace fs = std::filesystem;

void drawFigure4(const std::string& run_program, const std::string& scenario_path, const std::string& out) {
  char scratch[] = "/tmp/beft_figure4_XXXXXX";
  if (!mkdtemp(scratch)) throw std::runtime_error("cannot make a scratch folder");
  const std::string dir = scratch;
  // The whole 45 s: exploration keeps watching once everything is settled.
  const pid_t pid = fork();
  if (pid == 0) {
    // Killed, this program takes its run with it (beft-run stops its processes on SIGTERM).
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    const std::string log = dir + "/run_output.txt";
    freopen(log.c_str(), "w", stdout);
    freopen(log.c_str(), "a", stderr);
    execl(run_program.c_str(), run_program.c_str(), scenario_path.c_str(), "--set", "stop_when_done=0", "--out",
          dir.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  const fs::path weights = fs::path(dir) / "weights.png";
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(weights))
    throw std::runtime_error("the fig4_dw run failed; its output is in " + dir + "/run_output.txt");
  const std::string partial = partialPathFor(out);
  fs::copy_file(weights, partial, fs::copy_options::overwrite_existing);
  commitPartial(partial, out);
  fs::remove_all(dir);
}

}  // namespace beft::figure
