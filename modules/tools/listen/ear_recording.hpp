// The ears' blocks of a run (EARS) laid end to end as one stereo recording:
// each block at its first_sample, gaps (ticks whose block is missing) silent,
// a later block of the same samples replacing an earlier one (a restarted
// process re-publishing a tick).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <beft/binaural_block_t.hpp>

namespace beft::listen {

class EarRecording {
 public:
  // Blocks at another sample rate than the first block's, or that would make
  // the recording longer than max_seconds, are refused (false, why in *why).
  bool add(const binaural_block_t& block, std::string* why);

  int sampleRate() const { return sample_rate_; }
  int64_t firstSample() const { return first_sample_; }
  int64_t blocks() const { return blocks_; }
  // Interleaved left, right from firstSample() on, in the pressure the ears heard.
  const std::vector<float>& interleaved() const { return interleaved_; }
  // The largest magnitude of any sample (0 when silent or empty).
  float peak() const;

  static constexpr double kMaxSeconds = 4 * 3600;

 private:
  int sample_rate_ = 0;
  int64_t first_sample_ = -1;
  int64_t blocks_ = 0;
  std::vector<float> interleaved_;
};

// Writes the recording as a 16-bit stereo WAV (libsndfile), scaled by gain
// (samples beyond full scale are clipped); throws std::runtime_error naming
// the file on failure.
void writeWav(const EarRecording& recording, const std::string& path, double gain);

}  // namespace beft::listen
