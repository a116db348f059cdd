// The scene's sounds as mono signals at the ears' sample rate: each WAV file
// read once (libsndfile), its channels averaged, resampled with
// libsamplerate (band-limited sinc) when its rate differs.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "lib/hearing/binaural_renderer.hpp"

namespace beft::hearing {

class SoundBank {
 public:
  using Warning = std::function<void(const std::string&)>;
  // scenario_dir: what a scene object's `sound` is relative to.
  SoundBank(std::string scenario_dir, double sample_rate, Warning warn);

  // The sound of a scene object (its `sound` field, as the scenario wrote
  // it), loaded on first use. Null when it cannot be read, is empty, or is
  // longer than kMaxSeconds (the name comes from the bus: a lying message
  // must not make the process read a huge file); warned about once per name.
  const SourceSignal* sound(const std::string& relative_path);

  static constexpr double kMaxSeconds = 600;

 private:
  std::string scenario_dir_;
  double sample_rate_;
  Warning warn_;
  std::map<std::string, std::unique_ptr<SourceSignal>> loaded_;  // null: could not be read
};

// Reads a WAV (any format libsndfile reads) as mono at sample_rate; throws
// std::runtime_error naming the file and what is wrong.
SourceSignal readMonoSound(const std::string& path, double sample_rate, double max_seconds);

}  // namespace beft::hearing
