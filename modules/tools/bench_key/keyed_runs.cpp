#include "tools/bench_key/keyed_runs.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "lib/common/own_bin_dir.hpp"

namespace beft::bench {

RunFigures runYard(const std::string& dir, int ticks, const std::string& key_file) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string command = ownBinDir() + "/beft-run " + BEFT_SOURCE_DIR + "/scenarios/yard.xml --max-ticks " +
                              std::to_string(ticks) + " --out '" + dir + "'" +
                              (key_file.empty() ? "" : " --key '" + key_file + "'") + " > '" + dir +
                              "/out.txt' 2>&1";
  RunFigures figures;
  const int status = std::system(command.c_str());
  try {
    std::ifstream in(dir + "/report.json");
    const auto report = nlohmann::json::parse(in);
    figures.completed_run = status == 0;
    figures.ticks = report.value("ticks", 0LL);
    figures.ticks_per_s = report.value("ticks_per_s", 0.0);
    figures.refused = report.value("unauthenticated_total", 0LL);
  } catch (const std::exception&) {
    figures.completed_run = false;
  }
  return figures;
}

bool makeKey(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
  const std::string command = ownBinDir() + "/beft-key new '" + path + "' > /dev/null";
  return std::system(command.c_str()) == 0;
}

}  // namespace beft::bench
