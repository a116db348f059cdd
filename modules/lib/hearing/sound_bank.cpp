#include "lib/hearing/sound_bank.hpp"

#include <samplerate.h>
#include <sndfile.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace beft::hearing {

SourceSignal readMonoSound(const std::string& path, double sample_rate, double max_seconds) {
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (file == nullptr) throw std::runtime_error(path + ": cannot read as sound: " + sf_strerror(nullptr));
  struct Closer {
    SNDFILE* f;
    ~Closer() { sf_close(f); }
  } closer{file};
  if (info.channels < 1 || info.samplerate < 1) throw std::runtime_error(path + ": no channels or no sample rate");
  if (info.frames <= 0) throw std::runtime_error(path + ": no samples");
  if (static_cast<double>(info.frames) / info.samplerate > max_seconds)
    throw std::runtime_error(path + ": longer than " + std::to_string(static_cast<int>(max_seconds)) + " s");
  std::vector<float> interleaved(static_cast<std::size_t>(info.frames) * info.channels);
  const sf_count_t read = sf_readf_float(file, interleaved.data(), info.frames);
  if (read <= 0) throw std::runtime_error(path + ": no samples could be read");
  std::vector<float> mono(static_cast<std::size_t>(read));
  for (sf_count_t i = 0; i < read; ++i) {
    double sum = 0;
    for (int c = 0; c < info.channels; ++c) sum += interleaved[static_cast<std::size_t>(i) * info.channels + c];
    const double value = sum / info.channels;
    mono[static_cast<std::size_t>(i)] = std::isfinite(value) ? static_cast<float>(value) : 0.0f;
  }
  SourceSignal signal;
  if (info.samplerate == static_cast<int>(std::lround(sample_rate))) {
    signal.samples = std::move(mono);
    return signal;
  }
  const double ratio = sample_rate / info.samplerate;
  signal.samples.resize(static_cast<std::size_t>(std::ceil(mono.size() * ratio)) + 1);
  SRC_DATA data{};
  data.data_in = mono.data();
  data.input_frames = static_cast<long>(mono.size());
  data.data_out = signal.samples.data();
  data.output_frames = static_cast<long>(signal.samples.size());
  data.src_ratio = ratio;
  if (const int error = src_simple(&data, SRC_SINC_MEDIUM_QUALITY, 1); error != 0)
    throw std::runtime_error(path + ": resampling failed: " + src_strerror(error));
  signal.samples.resize(static_cast<std::size_t>(data.output_frames_gen));
  if (signal.samples.empty()) throw std::runtime_error(path + ": nothing left after resampling");
  return signal;
}

SoundBank::SoundBank(std::string scenario_dir, double sample_rate, Warning warn)
    : scenario_dir_(std::move(scenario_dir)), sample_rate_(sample_rate), warn_(std::move(warn)) {}

const SourceSignal* SoundBank::sound(const std::string& relative_path) {
  const auto found = loaded_.find(relative_path);
  if (found != loaded_.end()) return found->second.get();
  std::unique_ptr<SourceSignal> signal;
  const std::string path = (std::filesystem::path(scenario_dir_) / relative_path).string();
  try {
    if (relative_path.empty()) throw std::runtime_error("an object that sounds names no sound file");
    signal = std::make_unique<SourceSignal>(readMonoSound(path, sample_rate_, kMaxSeconds));
  } catch (const std::exception& e) {
    if (warn_) warn_(std::string(e.what()) + " (the object stays silent)");
  }
  return loaded_.emplace(relative_path, std::move(signal)).first->second.get();
}

}  // namespace beft::hearing
