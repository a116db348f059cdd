// beft-generate: writes generated scenarios (./beft generate district ...).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <optional>

#include "lib/common/command_line.hpp"
#include "tools/generate/generate_district.hpp"

namespace {

struct Options {
  std::string kind, out;
  std::vector<double> size = {80, 60};
  int objects = 110;
  uint64_t seed = 1;
  std::string sounds;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Writes a generated scenario in the contract format (scenario-format.md). 'district': a street grid "
      "of blocks with ruined houses open on one side (a person, a radio that sounds like a voice, or rubble "
      "inside), rubble, parked cars, sirens on poles, fires (some spreading later) and persons in the open, "
      "some calling for help, some starting to call later. The file is loaded back and every person checked "
      "reachable by the robot's footprint before it is written; the same arguments write the same file.",
      "beft-generate");
  app.add_option("kind", o.kind, "what to generate: district")->required()->check(CLI::IsMember({"district"}));
  app.add_option("--size", o.size, "world width and height [m]")->expected(2)->capture_default_str();
  app.add_option("--objects", o.objects, "number of objects (each wall counts one)")
      ->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the layout (also the scenario's seed)")->capture_default_str();
  app.add_option("--out", o.out, "scenario file to write")->required();
  app.add_option("--sounds", o.sounds,
                 "folder of the WAV files (help, voice_radio, siren, fire, engine), as written in the file "
                 "relative to it (default: the project's scenarios/sounds, relative to --out)");
  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  return std::nullopt;
}

// How the file was made, for its heading comment: the options by name
// without their dashes, as an XML comment may not hold "--".
std::string howMade(const Options& o) {
  return "./beft generate district, size " + std::to_string(static_cast<int>(o.size[0])) + " " +
         std::to_string(static_cast<int>(o.size[1])) + ", objects " + std::to_string(o.objects) + ", seed " +
         std::to_string(o.seed);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  beft::generate::DistrictParameters parameters;
  parameters.width = o.size[0];
  parameters.height = o.size[1];
  parameters.objects = o.objects;
  parameters.seed = o.seed;
  namespace fs = std::filesystem;
  const fs::path out_dir = fs::absolute(o.out).parent_path();
  parameters.sounds_dir = o.sounds.empty()
                              ? fs::relative(fs::path(BEFT_SOURCE_DIR) / "scenarios" / "sounds", out_dir).string()
                              : o.sounds;
  try {
    const auto generated = beft::generate::generateDistrict(parameters, o.out, howMade(o));
    const auto& d = generated.district;
    std::cout << o.out << ": " << d.objects.size() << " objects in " << o.size[0] << " x " << o.size[1] << " m: "
              << d.buildings << " houses, " << d.persons << " persons (" << d.calling_persons << " calling), "
              << d.radios << " radios, " << d.events.size() << " events, duration " << d.duration << " s"
              << (generated.attempts > 1 ? " (layout " + std::to_string(generated.attempts) + ")" : "") << "\n";
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "beft-generate: " << error.what() << "\n";
    return 1;
  }
}
