#include "lib/scenario/wav_info.hpp"

#include <sndfile.h>

namespace beft::scenario {

WavInfo readWavInfo(const std::string& path) {
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (file == nullptr) {
    throw WavError("cannot read '" + path + "' as audio: " + sf_strerror(nullptr));
  }
  sf_close(file);

  const int container = info.format & SF_FORMAT_TYPEMASK;
  if (container != SF_FORMAT_WAV && container != SF_FORMAT_WAVEX && container != SF_FORMAT_RF64) {
    throw WavError("'" + path + "' is audio but not a WAV file");
  }
  if (info.frames <= 0 || info.samplerate <= 0 || info.channels <= 0) {
    throw WavError("'" + path + "' is a WAV file with no samples");
  }
  WavInfo result;
  result.sample_rate = info.samplerate;
  result.channels = info.channels;
  result.frames = info.frames;
  result.duration = static_cast<double>(info.frames) / info.samplerate;
  return result;
}

}  // namespace beft::scenario
