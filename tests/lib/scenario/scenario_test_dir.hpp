// A fresh temporary folder per test, with a valid WAV (sounds/beep.wav) and a
// text file posing as one (sounds/not_a_wav.wav), to write scenario files into.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sndfile.h>
#include <unistd.h>

namespace beft::scenario::testing {

// Writes `seconds` of a quiet 440 Hz tone, mono 16 kHz 16-bit, in `format`.
inline void writeTone(const std::string& path, double seconds, int format = SF_FORMAT_WAV | SF_FORMAT_PCM_16) {
  SF_INFO info{};
  info.samplerate = 16000;
  info.channels = 1;
  info.format = format;
  SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
  ASSERT_NE(file, nullptr) << sf_strerror(nullptr);
  std::vector<short> samples(static_cast<size_t>(seconds * info.samplerate));
  for (size_t i = 0; i < samples.size(); ++i) samples[i] = static_cast<short>(1000 * ((i / 18) % 2 ? 1 : -1));
  sf_write_short(file, samples.data(), static_cast<sf_count_t>(samples.size()));
  sf_close(file);
}

// 1-based number of the first line of `text` containing `marker` (0 if none).
inline int lineOf(const std::string& text, const std::string& marker) {
  const auto at = text.find(marker);
  if (at == std::string::npos) return 0;
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

class ScenarioTestDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test->test_suite_name()) + "_" + test->name();
    for (char& c : name) {
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    dir_ = std::filesystem::temp_directory_path() / ("beft_scenario_" + std::to_string(getpid()) + "_" + name);
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "sounds");
    writeTone((dir_ / "sounds" / "beep.wav").string(), 0.5);
    std::ofstream((dir_ / "sounds" / "not_a_wav.wav").string()) << "this is text, not audio\n";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& text, const std::string& name = "scenario.xml") const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  std::filesystem::path dir_;
};

}  // namespace beft::scenario::testing
