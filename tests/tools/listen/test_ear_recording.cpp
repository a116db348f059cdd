// A run's ear blocks laid end to end, and the WAV written from them.
#include <gtest/gtest.h>
#include <sndfile.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "tools/listen/ear_recording.hpp"

using namespace beft;

namespace {

binaural_block_t block(int64_t first_sample, int count, int16_t left, int16_t right, double full_scale = 0.5) {
  binaural_block_t b{};
  b.sample_rate = 44100;
  b.first_sample = first_sample;
  b.full_scale = full_scale;
  b.num_samples = count;
  b.left.assign(static_cast<std::size_t>(count), left);
  b.right.assign(static_cast<std::size_t>(count), right);
  return b;
}

}  // namespace

TEST(EarRecording, PutsEachBlockAtItsSamplesWithGapsSilent) {
  listen::EarRecording recording;
  std::string why;
  ASSERT_TRUE(recording.add(block(100, 10, 32767, -32767), &why));
  ASSERT_TRUE(recording.add(block(120, 10, 16384, 0), &why));  // ticks 110..119 missing
  ASSERT_TRUE(recording.add(block(90, 10, 0, 32767), &why));   // an earlier block heard late
  EXPECT_EQ(recording.firstSample(), 90);
  EXPECT_EQ(recording.blocks(), 3);
  const auto& s = recording.interleaved();
  ASSERT_EQ(s.size(), 2u * 40);
  EXPECT_FLOAT_EQ(s[2 * 0 + 1], 0.5f);    // sample 90, right
  EXPECT_FLOAT_EQ(s[2 * 10], 0.5f);       // sample 100, left
  EXPECT_FLOAT_EQ(s[2 * 10 + 1], -0.5f);  // sample 100, right
  EXPECT_FLOAT_EQ(s[2 * 25], 0.0f);       // sample 115: the gap
  EXPECT_NEAR(s[2 * 30], 0.25f, 1e-4);    // sample 120
  EXPECT_FLOAT_EQ(recording.peak(), 0.5f);
  // A block published again (a restarted process) replaces the first one.
  ASSERT_TRUE(recording.add(block(100, 10, 0, 0), &why));
  EXPECT_FLOAT_EQ(recording.interleaved()[2 * 10], 0.0f);
}

TEST(EarRecording, RefusesBlocksThatDoNotFit) {
  listen::EarRecording recording;
  std::string why;
  ASSERT_TRUE(recording.add(block(0, 10, 1, 1), &why));
  auto other_rate = block(10, 10, 1, 1);
  other_rate.sample_rate = 48000;
  EXPECT_FALSE(recording.add(other_rate, &why));
  EXPECT_NE(why.find("48000"), std::string::npos) << why;
  EXPECT_FALSE(recording.add(block(10, 10, 1, 1, std::nan("")), &why));
  // A lying first_sample would make a recording of days.
  EXPECT_FALSE(recording.add(block(int64_t{1} << 40, 10, 1, 1), &why));
  EXPECT_NE(why.find("longer than"), std::string::npos) << why;
  // num_samples beyond the arrays: only what the arrays hold.
  auto lying = block(10, 5, 1, 1);
  lying.num_samples = 1000000;
  ASSERT_TRUE(recording.add(lying, &why));
  EXPECT_EQ(recording.interleaved().size(), 2u * 15);
}

TEST(EarRecording, WritesAStereoWavTheEarsCanBeHeardFrom) {
  listen::EarRecording recording;
  std::string why;
  ASSERT_TRUE(recording.add(block(0, 441, 32767, -16384), &why));
  char name[] = "/tmp/beft_listen_XXXXXX";
  const int fd = mkstemp(name);
  ASSERT_GE(fd, 0);
  close(fd);
  const std::string path = std::string(name) + ".wav";
  listen::writeWav(recording, path, 2.0);  // 0.5 * 2 = full scale, -0.25 * 2 = -0.5
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  ASSERT_NE(file, nullptr);
  EXPECT_EQ(info.channels, 2);
  EXPECT_EQ(info.samplerate, 44100);
  EXPECT_EQ(info.frames, 441);
  std::vector<float> samples(2 * 441);
  sf_readf_float(file, samples.data(), 441);
  sf_close(file);
  EXPECT_NEAR(samples[0], 1.0f, 1e-3);
  EXPECT_NEAR(samples[1], -0.5f, 1e-3);
  std::remove(name);
  std::remove(path.c_str());
  EXPECT_THROW(listen::writeWav(recording, "/nonexistent-folder/ears.wav", 1.0), std::runtime_error);
}
