#include "tools/view/run_net.hpp"

#include <filesystem>
#include <fstream>

namespace beft::view {

std::string netOfRun(const std::string& processes_log) {
  std::ifstream log(processes_log);
  const std::string marker = "[arbiter] info: net ";
  for (std::string line; std::getline(log, line);) {
    const auto at = line.find(marker);
    if (at == std::string::npos) continue;
    const auto from = at + marker.size();
    const auto end = line.find(": ", from);  // the path ends where the net's summary begins
    if (end == std::string::npos) continue;
    const std::string path = line.substr(from, end - from);
    std::error_code error;
    return std::filesystem::is_regular_file(path, error) ? path : "";
  }
  return "";
}

}  // namespace beft::view
