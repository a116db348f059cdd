#include "tools/bench_view/bridge_usage.hpp"

#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "tools/bench_view/child_process.hpp"

namespace beft::bench {

namespace {

// Whether /proc/PID/cmdline (arguments split by NUL) is beft-bridge's with --port `port`.
bool servesPort(const std::string& cmdline, int port) {
  return cmdline.find("beft-bridge") != std::string::npos &&
         cmdline.find(std::string("--port") + '\0' + std::to_string(port) + '\0') != std::string::npos;
}

// utime + stime of /proc/PID/stat (fields 14 and 15, counted after the command's closing parenthesis).
double cpuSeconds(const std::string& stat) {
  const auto after = stat.rfind(')');
  if (after == std::string::npos) return -1;
  std::istringstream fields(stat.substr(after + 2));
  std::string field;
  for (int i = 3; i < 14 && fields >> field; ++i) {
  }
  long long user = 0, system = 0;
  if (!(fields >> user >> system)) return -1;
  return static_cast<double>(user + system) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

}  // namespace

BridgeUsage bridgeUsage(int port) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
    const std::string pid = entry.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (!servesPort(readFile(entry.path().string() + "/cmdline"), port)) continue;
    BridgeUsage usage;
    const std::string rss = lineAfter(readFile(entry.path().string() + "/status"), "VmRSS:");
    usage.rss_kb = rss.empty() ? -1 : std::stol(rss);
    usage.cpu_s = cpuSeconds(readFile(entry.path().string() + "/stat"));
    return usage;
  }
  return {};
}

}  // namespace beft::bench
