// HRIR sets: the KEMAR file's layout and interpolation, the spherical-head
// model, and clear refusals of files that are not an HRIR set.
#include <gtest/gtest.h>
#include <sndfile.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "lib/hearing/binaural_cues.hpp"
#include "tests/lib/hearing/hearing_test_support.hpp"
#include "lib/hearing/hrir_set.hpp"

using namespace beft::hearing;
using namespace beft::hearing::test;

#define REQUIRE_KEMAR()                                                                                \
  if (!kemarInstalled())                                                                               \
  GTEST_SKIP() << HrirSet::kKemarPath << " is missing (Debian package " << HrirSet::kKemarPackage << ")"

namespace {

std::string temporaryPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("beft_hrir_" + std::to_string(getpid()) + "_" + name)).string();
}

// Writes `channels` channels of `frames` samples; sample(channel, frame) gives each.
template <typename Sample>
void writeWav(const std::string& path, int channels, int frames, Sample sample) {
  SF_INFO info{};
  info.channels = channels;
  info.samplerate = 44100;
  info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
  SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
  ASSERT_NE(file, nullptr) << sf_strerror(nullptr);
  std::vector<float> data(static_cast<std::size_t>(channels) * frames);
  for (int f = 0; f < frames; ++f)
    for (int c = 0; c < channels; ++c) data[static_cast<std::size_t>(f) * channels + c] = sample(c, f);
  sf_writef_float(file, data.data(), frames);
  sf_close(file);
}

// An impulse per channel: the ear facing the source earlier and louder,
// at 4 directions (0, 90, 180, 270 degrees); `swap` exchanges the ears.
float toyResponse(int channel, int frame, bool swap) {
  const int direction = channel / 2;
  bool left = channel % 2 == 0;
  if (swap) left = !left;
  const bool near = (direction == 1 && left) || (direction == 3 && !left);
  const bool far = (direction == 1 && !left) || (direction == 3 && left);
  if (near) return frame == 10 ? 1.0f : 0.0f;
  if (far) return frame == 40 ? 0.2f : 0.0f;
  return frame == 20 ? 0.5f : 0.0f;
}

std::string messageOf(const std::string& path) {
  try {
    HrirSet::loadKemar(path);
  } catch (const HrirError& error) {
    return error.what();
  }
  return "";
}

double energy(const float* x, int n) {
  double sum = 0;
  for (int i = 0; i < n; ++i) sum += double(x[i]) * x[i];
  return sum;
}

}  // namespace

TEST(KemarSet, HasTheShippedLayout) {
  REQUIRE_KEMAR();
  const HrirSet& set = kemar();
  EXPECT_EQ(set.directionCount(), 360);
  EXPECT_EQ(set.length(), 512);
  EXPECT_EQ(set.sampleRate(), 44100);
  EXPECT_DOUBLE_EQ(set.directionStepDeg(), 1.0);
  // Sound from ahead reaches the ears about 1.45 ms into the responses.
  EXPECT_GT(set.centreDelaySamples(), 40);
  EXPECT_LT(set.centreDelaySamples(), 80);
}

TEST(KemarSet, ALeftSourceReachesTheLeftEarFirstAndLouder) {
  REQUIRE_KEMAR();
  const HrirSet& set = kemar();
  const int n = set.length();
  EXPECT_GT(energy(set.response(90, Ear::Left), n), 10 * energy(set.response(90, Ear::Right), n));
  EXPECT_GT(energy(set.response(270, Ear::Right), n), 10 * energy(set.response(270, Ear::Left), n));
  // Ahead, both ears alike (within 1 dB).
  const double front = energy(set.response(0, Ear::Left), n) / energy(set.response(0, Ear::Right), n);
  EXPECT_NEAR(10 * std::log10(front), 0, 1.0);
}

TEST(KemarSet, InterpolatesBetweenNeighboursAndWraps) {
  REQUIRE_KEMAR();
  const HrirSet& set = kemar();
  const int n = set.length();
  std::vector<float> left(n), right(n), left2(n), right2(n);
  set.responsesAt(30, left.data(), right.data());
  for (int i = 0; i < n; ++i) ASSERT_EQ(left[i], set.response(30, Ear::Left)[i]);
  set.responsesAt(30.5, left.data(), right.data());
  for (int i = 0; i < n; ++i) {
    ASSERT_NEAR(left[i], 0.5f * (set.response(30, Ear::Left)[i] + set.response(31, Ear::Left)[i]), 1e-6);
    ASSERT_NEAR(right[i], 0.5f * (set.response(30, Ear::Right)[i] + set.response(31, Ear::Right)[i]), 1e-6);
  }
  set.responsesAt(-90, left.data(), right.data());
  set.responsesAt(270 + 720, left2.data(), right2.data());
  EXPECT_EQ(left, left2);
  EXPECT_EQ(right, right2);
  set.responsesAt(359.5, left.data(), right.data());  // between 359 and 0
  for (int i = 0; i < n; ++i)
    ASSERT_NEAR(left[i], 0.5f * (set.response(359, Ear::Left)[i] + set.response(0, Ear::Left)[i]), 1e-6);
}

TEST(KemarLoader, SaysWhichFileIsMissing) {
  const std::string message = messageOf(temporaryPath("absent.wav"));
  EXPECT_NE(message.find("absent.wav"), std::string::npos) << message;
  EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

TEST(KemarLoader, RefusesAFileThatIsNotAudio) {
  const std::string path = temporaryPath("text.wav");
  std::ofstream(path) << "RIFF? no, just text\n";
  const std::string message = messageOf(path);
  std::filesystem::remove(path);
  EXPECT_NE(message.find("cannot read HRIR set"), std::string::npos) << message;
  EXPECT_NE(message.find(path), std::string::npos) << message;
}

TEST(KemarLoader, RefusesAnOddChannelCount) {
  const std::string path = temporaryPath("odd.wav");
  writeWav(path, 3, 64, [](int, int f) { return f == 0 ? 1.0f : 0.0f; });
  const std::string message = messageOf(path);
  std::filesystem::remove(path);
  EXPECT_NE(message.find("has 3 channels"), std::string::npos) << message;
}

TEST(KemarLoader, RefusesNonFiniteSamples) {
  const std::string path = temporaryPath("nan.wav");
  writeWav(path, 8, 64, [](int c, int f) { return c == 5 && f == 7 ? NAN : toyResponse(c, f, false); });
  const std::string message = messageOf(path);
  std::filesystem::remove(path);
  EXPECT_NE(message.find("channel 5"), std::string::npos) << message;
  EXPECT_NE(message.find("not finite"), std::string::npos) << message;
}

TEST(KemarLoader, RefusesSilence) {
  const std::string path = temporaryPath("silent.wav");
  writeWav(path, 8, 64, [](int, int) { return 0.0f; });
  const std::string message = messageOf(path);
  std::filesystem::remove(path);
  EXPECT_NE(message.find("silent"), std::string::npos) << message;
}

TEST(KemarLoader, RefusesEarsTheWrongWayRound) {
  const std::string good = temporaryPath("good.wav"), swapped = temporaryPath("swapped.wav");
  writeWav(good, 8, 64, [](int c, int f) { return toyResponse(c, f, false); });
  writeWav(swapped, 8, 64, [](int c, int f) { return toyResponse(c, f, true); });
  const HrirSet set = HrirSet::loadKemar(good);
  EXPECT_EQ(set.directionCount(), 4);
  EXPECT_DOUBLE_EQ(set.centreDelaySamples(), 20);
  const std::string message = messageOf(swapped);
  std::filesystem::remove(good);
  std::filesystem::remove(swapped);
  EXPECT_NE(message.find("does not reach the left ear first"), std::string::npos) << message;
  EXPECT_NE(message.find("channels 2 and 3"), std::string::npos) << message;
}

TEST(DefaultSet, FallsBackToTheSphericalHeadWithAWarning) {
  std::vector<std::string> warnings;
  const HrirSet set =
      HrirSet::loadDefault([&](const std::string& w) { warnings.push_back(w); }, temporaryPath("gone.wav"));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("gone.wav"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("spherical-head"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find(HrirSet::kKemarPackage), std::string::npos) << warnings[0];
  EXPECT_NE(set.name().find("spherical-head"), std::string::npos);
}

TEST(DefaultSet, TakesTheKemarFileWhenThere) {
  REQUIRE_KEMAR();
  std::vector<std::string> warnings;
  const HrirSet set = HrirSet::loadDefault([&](const std::string& w) { warnings.push_back(w); });
  EXPECT_TRUE(warnings.empty());
  EXPECT_NE(set.name().find("KEMAR"), std::string::npos);
}

TEST(SphericalHead, ShadowsTheFarEarAndDelaysIt) {
  const HrirSet set = HrirSet::sphericalHead(44100);
  EXPECT_EQ(set.directionCount(), 360);
  const int n = set.length();
  const std::vector<float> left_at_minus_90(set.response(270, Ear::Left), set.response(270, Ear::Left) + n);
  const std::vector<float> right_at_minus_90(set.response(270, Ear::Right), set.response(270, Ear::Right) + n);
  // A source on the right: the right ear louder, above all in the highs.
  EXPECT_GT(interauralLevelDifferenceDb(right_at_minus_90, left_at_minus_90, 44100, 4000, 1e12, Window::Rectangular),
            10);
  // Woodworth with a = 8.75 cm and ears at +-100 deg: at 90 deg the ITD
  // is a/c (cos 10 deg + 80 deg in rad) = 0.607 ms.
  EXPECT_NEAR(interauralTimeDifferenceMs(left_at_minus_90, right_at_minus_90, 44100), -0.607, 0.05);
  // Ahead: the ears alike.
  const std::vector<float> left_ahead(set.response(0, Ear::Left), set.response(0, Ear::Left) + n);
  const std::vector<float> right_ahead(set.response(0, Ear::Right), set.response(0, Ear::Right) + n);
  EXPECT_NEAR(interauralTimeDifferenceMs(left_ahead, right_ahead, 44100), 0, 0.01);
  EXPECT_NEAR(interauralLevelDifferenceDb(left_ahead, right_ahead, 44100, 0, 1e12, Window::Rectangular), 0, 0.01);
}

TEST(SphericalHead, RefusesAnImplausibleSampleRate) {
  EXPECT_THROW(HrirSet::sphericalHead(0), HrirError);
  EXPECT_THROW(HrirSet::sphericalHead(NAN), HrirError);
}
