// Missions that hear for real (./beft run --acoustics binaural): the ears
// process renders what the head hears, the audio expert localises it; the
// shipped scenarios' promises still hold, the estimates are heard (not
// given), the run replays and survives killed processes unchanged, and
// beft-listen turns it into a WAV.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include <beft/acoustic_percepts_t.hpp>
#include <beft/binaural_block_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_command_t.hpp>

#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

struct HearingRun {
  std::string dir;
  ProgramResult result;
  std::vector<LoggedMessage> log;
  nlohmann::json report;
};

const HearingRun& hearingRun(const std::string& scenario, const std::string& extra_args = "") {
  static std::map<std::string, HearingRun> runs;
  const std::string key = scenario + " " + extra_args;
  if (const auto it = runs.find(key); it != runs.end()) return it->second;
  HearingRun run;
  run.dir = makeTempDir("hearing_" + scenario);
  run.result = runCommand(binDir() + "/beft-run " + sourceDir() + "/scenarios/" + scenario +
                              ".xml --acoustics binaural --out " + run.dir + " " + extra_args,
                          600);
  try {
    run.log = readLog(run.dir + "/run.lcmlog");
    run.report = readJson(run.dir + "/report.json");
  } catch (const std::exception& e) {
    run.result.output += std::string("\n[test] ") + e.what();
  }
  return runs.emplace(key, std::move(run)).first->second;
}

std::set<std::string> victimsOf(const nlohmann::json& report) {
  std::set<std::string> ids;
  for (const auto& v : report["victims"]) ids.insert(v["object"].get<std::string>());
  return ids;
}

}  // namespace

TEST(HearingMissions, YardPeekAndDecoyFindEveryPersonFromWhatTheEarsHeard) {
  for (const char* scenario : {"yard", "peek", "decoy"}) {
    const auto& run = hearingRun(scenario);
    ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
    EXPECT_TRUE(run.report["missed"].empty()) << scenario << ": " << run.report.dump(2);
    EXPECT_EQ(static_cast<int>(victimsOf(run.report).size()), run.report["persons"].get<int>()) << scenario;
    EXPECT_EQ(run.report["collisions"], 0) << scenario;
    EXPECT_FALSE(run.report["heard"].empty()) << scenario;
    for (const auto& heard : run.report["heard"])
      EXPECT_LT(heard["error_m"].get<double>(), 3.0) << scenario << ": " << heard.dump();
  }
  bool radio_falsified = false;
  for (const auto& f : hearingRun("decoy").report["falsified"]) radio_falsified |= f["object"] == "radio";
  EXPECT_TRUE(radio_falsified) << hearingRun("decoy").report.dump(2);
}

TEST(HearingMissions, DecoyInAReverberantYardFindsTheCallerInTheHouse) {
  // decoy_reverb: <acoustics> T60 0.6 s, so the audio expert localises with
  // the reverberant profile; with the free-field one the caller is missed.
  const auto& run = hearingRun("decoy_reverb");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  EXPECT_TRUE(run.report["missed"].empty()) << run.report.dump(2);
  EXPECT_EQ(victimsOf(run.report), (std::set<std::string>{"victim", "caller"})) << run.report.dump(2);
  EXPECT_EQ(run.report["collisions"], 0);
  bool radio_falsified = false;
  for (const auto& f : run.report["falsified"]) radio_falsified |= f["object"] == "radio";
  EXPECT_TRUE(radio_falsified) << run.report.dump(2);
}

TEST(HearingMissions, EstimatesComeFromTheEarsNotFromGroundTruth) {
  const auto& run = hearingRun("yard");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto blocks = messagesOn<beft::binaural_block_t>(run.log, "EARS");
  const auto scenes = messagesOn<beft::scene_objects_t>(run.log, "GT_OBJECTS");
  ASSERT_GT(blocks.size(), 100u);
  // The blocks follow one another without a gap or overlap, 0.1 s each.
  int64_t next = -1, loud = 0;
  for (const auto& block : blocks) {
    if (next >= 0 && block.first_sample != 0) {
      EXPECT_EQ(block.first_sample, next) << "tick " << block.tick;
    }
    next = block.first_sample + block.num_samples;
    if (block.num_samples > 0) {
      EXPECT_EQ(block.num_samples, 4410) << "tick " << block.tick;
    }
    loud += block.full_scale > 1e-3;
  }
  EXPECT_GT(loud * 2, static_cast<int64_t>(blocks.size())) << "the ears heard nothing most of the time";
  // Positions differ from the truth by what hearing gets wrong, not by nothing.
  std::map<int64_t, const beft::scene_objects_t*> scene_of_tick;
  for (const auto& scene : scenes) scene_of_tick[scene.tick] = &scene;
  int compared = 0, exact = 0;
  for (const auto& audio : messagesOn<beft::acoustic_percepts_t>(run.log, "AUDIO")) {
    auto scene = scene_of_tick.upper_bound(audio.tick);  // the ground truth in force: the last one sent
    if (scene == scene_of_tick.begin()) continue;
    --scene;
    for (const auto& percept : audio.percepts)
      for (const auto& object : scene->second->objects)
        if (object.id == percept.object_id) {
          ++compared;
          exact += std::hypot(percept.est_x - object.x, percept.est_y - object.y) < 1e-6;
        }
  }
  EXPECT_GT(compared, 100);
  EXPECT_EQ(exact, 0);
}

TEST(HearingMissions, TheAudioExpertReplaysExactlyAndTheEarsCanBeListenedTo) {
  const auto& run = hearingRun("yard");
  ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
  const auto replay = runCommand(binDir() + "/beft-replay " + run.dir + "/run.lcmlog --module audio", 300);
  EXPECT_EQ(replay.exit_code, 0) << replay.output;
  EXPECT_NE(replay.output.find("EXACT MATCH"), std::string::npos) << replay.output;

  const std::string wav = run.dir + "/ears.wav";
  const auto listen = runCommand(binDir() + "/beft-listen " + run.dir + "/run.lcmlog --out " + wav, 120);
  ASSERT_EQ(listen.exit_code, 0) << listen.output;
  SF_INFO info{};
  SNDFILE* file = sf_open(wav.c_str(), SFM_READ, &info);
  ASSERT_NE(file, nullptr) << listen.output;
  sf_close(file);
  EXPECT_EQ(info.channels, 2);
  EXPECT_EQ(info.samplerate, 44100);
  const auto blocks = messagesOn<beft::binaural_block_t>(run.log, "EARS");
  EXPECT_NEAR(static_cast<double>(info.frames), 4410.0 * (blocks.size() - 1), 4410.0 * 2);
}

TEST(HearingMissions, KilledEarsAndAudioResumeAndTheRunsMessagesDoNotChange) {
  const auto& clean = hearingRun("yard");
  ASSERT_EQ(clean.result.exit_code, 0) << clean.result.output;
  const auto& killed = hearingRun("yard", "--kill ears@60 --kill audio@150");
  ASSERT_EQ(killed.result.exit_code, 0) << killed.result.output;
  // Nothing is sent twice: a restarted process resumes where it was.
  std::size_t repeats = 0;
  withoutRepeats(killed.log, repeats);
  EXPECT_EQ(repeats, 0u) << "data messages sent twice";
  const DataComparison comparison = compareDataMessages(clean.log, killed.log);
  EXPECT_GT(comparison.expected, 1000u);
  EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
  EXPECT_EQ(killed.report["ticks"], clean.report["ticks"]);
}
