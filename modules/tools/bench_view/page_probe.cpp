#include "tools/bench_view/page_probe.hpp"

#include <signal.h>

#include <filesystem>
#include <sstream>

#include "lib/common/own_bin_dir.hpp"
#include "tools/bench_view/child_process.hpp"

namespace beft::bench {

namespace {

std::string nodeCommand(const std::string& arguments) {
  return "cd " + shellQuoted(probeFolder()) + " && exec node page_probe.mjs " + arguments;
}

}  // namespace

std::string probeFolder() { return ownBinDir() + "/../share/beft/bench_view"; }

std::string probeUnavailable(const std::string& work) {
  for (const char* program : {"beft-bridge", "beft-control"})
    if (!std::filesystem::exists(ownBinDir() + "/" + program)) return std::string(program) + " is not built";
  if (!std::filesystem::exists(ownBinDir() + "/../share/beft/web/app.js"))
    return "the viewer page is not built (target beft_web)";
  if (runShell("command -v node > /dev/null") != 0) return "node is not installed (Debian package nodejs)";
  if (!std::filesystem::exists(probeFolder() + "/page_probe.mjs"))
    return "page_probe.mjs is not in " + probeFolder() + " (build the target beft-bench-view)";
  const std::string out = work + "/probe_check.txt";
  runShell(nodeCommand("--check > " + shellQuoted(out) + " 2>&1"));
  const std::string text = readFile(out);
  const std::string why = lineAfter(text, "unavailable: ");
  if (!why.empty()) return why;
  return lineAfter(text, "browser: ").empty() ? "the browser did not start: " + text : "";
}

PageProbe::PageProbe(const std::string& url, int every_ms, double seconds, const std::string& output_file)
    : output_file_(output_file) {
  std::ostringstream arguments;
  arguments << "--url " << shellQuoted(url) << " --every-ms " << every_ms << " --seconds " << seconds << " > "
            << shellQuoted(output_file) << " 2>&1";
  pid_ = startShell(nodeCommand(arguments.str()));
}

PageProbe::~PageProbe() { stop(); }

PageReadings PageProbe::readings() const { return parseProbeOutput(readFile(output_file_)); }

bool PageProbe::ended() const {
  if (!ended_) ended_ = hasEnded(pid_);
  return ended_;
}

void PageProbe::stop() {
  if (!ended_) stopGroup(pid_, SIGTERM, 20);
  ended_ = true;
}

PageReadings parseProbeOutput(const std::string& text) {
  PageReadings readings;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "unavailable:") readings.unavailable = line.substr(kind.size() + 1);
    if (kind == "connected:") fields >> readings.connected_ms;
    if (kind == "page") readings.page_errors.push_back(line);
    if (kind != "sample:") continue;
    PageSample s;
    fields >> s.wall_ms >> s.tick >> s.frame_time_ms >> s.frames >> s.renders >> s.objects >> s.hypotheses;
    if (fields) readings.samples.push_back(s);
  }
  return readings;
}

}  // namespace beft::bench
