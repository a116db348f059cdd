// beft-listen: what the robot's ears heard in a recorded run, as a WAV file
// (see --help).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <optional>

#include "lib/common/channels.hpp"
#include "lib/common/command_line.hpp"
#include "tools/listen/ear_recording.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/run_identity.hpp"

namespace {

using namespace beft;

struct Options {
  std::string log_path, out = "ears.wav";
  double gain_db = std::nan("");  // default: the loudest sample at -1 dBFS
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Writes what the robot's two ears heard in a run (the EARS channel of a run made with ./beft run "
      "--acoustics binaural) as a 16-bit stereo WAV, left ear left: put on headphones and listen from the "
      "robot's head. Ticks whose block the log lacks are silent. By default the loudest sample is set "
      "to -1 dBFS; --gain-db sets a fixed gain instead (0: the rendered pressure, 1.0 = full scale).",
      "beft-listen");
  app.add_option("log", o.log_path, "the run's LCM log (run.lcmlog)")->required()->check(CLI::ExistingFile);
  app.add_option("--out", o.out, "WAV file to write")->capture_default_str();
  app.add_option("--gain-db", o.gain_db, "fixed gain [dB] instead of normalising to the loudest sample");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// The EARS blocks of the log's run; `refused` counts those that did not fit
// (the first is reported), and damage to the log is reported.
listen::EarRecording recordEars(const std::string& log_path, int64_t& refused) {
  const int64_t run = wire::runId() != 0 ? wire::runId() : wire::runOfLog(log_path);
  wire::LogReader log(log_path);
  listen::EarRecording recording;
  wire::LogEvent event;
  while (log.nextOfRun(event, run)) {
    if (event.channel != channels::kEars) continue;
    binaural_block_t block{};
    std::string why;
    if (!wire::decodeFrom(event.channel, event.data.data(), event.data.size(), block) ||
        !recording.add(block, &why)) {
      if (!why.empty() && refused == 0) std::fprintf(stderr, "beft-listen: block of tick %lld refused: %s\n",
                                                     static_cast<long long>(block.tick), why.c_str());
      ++refused;
    }
  }
  if (!log.damage().summary().empty()) std::fprintf(stderr, "beft-listen: %s\n", log.damage().summary().c_str());
  return recording;
}

// --gain-db, or the gain that puts the loudest sample at -1 dBFS.
double outputGain(const Options& o, float peak) {
  return std::isnan(o.gain_db) ? (peak > 0 ? std::pow(10.0, -1.0 / 20) / peak : 1.0) : std::pow(10.0, o.gain_db / 20);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  try {
    int64_t refused = 0;
    const listen::EarRecording recording = recordEars(o.log_path, refused);
    if (recording.blocks() == 0) {
      std::fprintf(stderr,
                   "beft-listen: %s holds no EARS blocks: record the run with ./beft run SCENARIO --acoustics "
                   "binaural\n",
                   o.log_path.c_str());
      return 1;
    }
    const double gain = outputGain(o, recording.peak());
    listen::writeWav(recording, o.out, gain);
    const double seconds = static_cast<double>(recording.interleaved().size() / 2) / recording.sampleRate();
    std::printf("%s: %.1f s from %lld blocks at %d Hz, gain %+.1f dB%s\n", o.out.c_str(), seconds,
                static_cast<long long>(recording.blocks()), recording.sampleRate(), 20 * std::log10(gain),
                refused > 0 ? (", " + std::to_string(refused) + " blocks refused").c_str() : "");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-listen: %s\n", e.what());
    return 1;
  }
}
