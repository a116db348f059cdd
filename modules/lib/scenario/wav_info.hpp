// What a WAV file holds, read through libsndfile; used to refuse sound files
// that are missing or unreadable before any process starts.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace beft::scenario {

struct WavInfo {
  int sample_rate = 0;     // [Hz]
  int channels = 0;
  int64_t frames = 0;      // samples per channel
  double duration = 0;     // [s]
};

class WavError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws WavError ("cannot open ...", "is not a WAV file", "has no samples").
WavInfo readWavInfo(const std::string& path);

}  // namespace beft::scenario
