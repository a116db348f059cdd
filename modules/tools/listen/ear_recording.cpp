#include "tools/listen/ear_recording.hpp"

#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beft::listen {

bool EarRecording::add(const binaural_block_t& block, std::string* why) {
  if (block.sample_rate <= 0 || (sample_rate_ != 0 && block.sample_rate != sample_rate_)) {
    *why = "sample rate " + std::to_string(block.sample_rate) + " Hz, the recording's is " +
           std::to_string(sample_rate_) + " Hz";
    return false;
  }
  if (!(block.full_scale > 0) || !std::isfinite(block.full_scale)) {
    *why = "full_scale is not a positive number";
    return false;
  }
  const int64_t count = std::min<int64_t>({block.num_samples, static_cast<int64_t>(block.left.size()),
                                           static_cast<int64_t>(block.right.size())});
  if (count <= 0) return true;  // nothing heard in that tick
  const int64_t start = first_sample_ < 0 ? block.first_sample : std::min(first_sample_, block.first_sample);
  const int64_t end = std::max(first_sample_ < 0 ? 0 : first_sample_ + static_cast<int64_t>(interleaved_.size() / 2),
                               block.first_sample + count);
  if (static_cast<double>(end - start) > kMaxSeconds * block.sample_rate) {
    *why = "the recording would be longer than " + std::to_string(static_cast<int>(kMaxSeconds)) + " s";
    return false;
  }
  if (first_sample_ >= 0 && start < first_sample_)  // a block before everything so far: shift what there is
    interleaved_.insert(interleaved_.begin(), static_cast<std::size_t>(2 * (first_sample_ - start)), 0.0f);
  first_sample_ = start;
  sample_rate_ = block.sample_rate;
  interleaved_.resize(static_cast<std::size_t>(2 * (end - start)), 0.0f);
  const double scale = block.full_scale / 32767.0;
  for (int64_t i = 0; i < count; ++i) {
    const std::size_t at = static_cast<std::size_t>(2 * (block.first_sample - start + i));
    interleaved_[at] = static_cast<float>(block.left[static_cast<std::size_t>(i)] * scale);
    interleaved_[at + 1] = static_cast<float>(block.right[static_cast<std::size_t>(i)] * scale);
  }
  ++blocks_;
  return true;
}

float EarRecording::peak() const {
  float peak = 0;
  for (const float value : interleaved_) peak = std::max(peak, std::fabs(value));
  return peak;
}

void writeWav(const EarRecording& recording, const std::string& path, double gain) {
  SF_INFO info{};
  info.samplerate = recording.sampleRate() > 0 ? recording.sampleRate() : 44100;
  info.channels = 2;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
  if (file == nullptr) throw std::runtime_error(path + ": cannot write: " + sf_strerror(nullptr));
  std::vector<float> scaled(recording.interleaved());
  for (float& value : scaled) value = static_cast<float>(std::clamp(value * gain, -1.0, 1.0));
  const sf_count_t frames = static_cast<sf_count_t>(scaled.size() / 2);
  const sf_count_t written = sf_writef_float(file, scaled.data(), frames);
  sf_close(file);
  if (written != frames) throw std::runtime_error(path + ": could not write every sample (disk full?)");
}

}  // namespace beft::listen
