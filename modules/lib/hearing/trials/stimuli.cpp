#include "lib/hearing/trials/stimuli.hpp"

#include <sndfile.h>

#include "lib/hearing/hrir_set.hpp"

#include <cmath>
#include <stdexcept>

namespace beft::hearing::trials {

namespace {
void scaleTo(std::vector<float>& samples, float rms) {
  double sum = 0;
  for (float s : samples) sum += static_cast<double>(s) * s;
  const double current = std::sqrt(sum / samples.size());
  for (float& s : samples) s = static_cast<float>(s * rms / current);
}
}  // namespace

std::vector<float> whiteNoise(int samples, std::mt19937_64& random, float rms) {
  std::normal_distribution<float> gauss(0, 1);
  std::vector<float> out(static_cast<std::size_t>(samples));
  for (float& s : out) s = gauss(random);
  scaleTo(out, rms);
  return out;
}

std::vector<float> pinkNoise(int samples, std::mt19937_64& random, float rms) {
  // Paul Kellet's filter: white noise through a sum of first-order low-passes, -3 dB per octave.
  std::normal_distribution<double> gauss(0, 1);
  std::vector<float> out(static_cast<std::size_t>(samples));
  double b[7] = {};
  for (float& s : out) {
    const double w = gauss(random);
    b[0] = 0.99886 * b[0] + w * 0.0555179;
    b[1] = 0.99332 * b[1] + w * 0.0750759;
    b[2] = 0.96900 * b[2] + w * 0.1538520;
    b[3] = 0.86650 * b[3] + w * 0.3104856;
    b[4] = 0.55000 * b[4] + w * 0.5329522;
    b[5] = -0.7616 * b[5] - w * 0.0168980;
    s = static_cast<float>(b[0] + b[1] + b[2] + b[3] + b[4] + b[5] + b[6] + w * 0.5362);
    b[6] = w * 0.115926;
  }
  scaleTo(out, rms);
  return out;
}

std::string scenarioSoundsDir() { return BEFT_SOUNDS_DIR; }

std::vector<float> scenarioSound(const std::string& name, float rms, const std::string& dir) {
  const std::string path = dir + "/" + name + ".wav";
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (file == nullptr || info.channels != 1) throw std::runtime_error("cannot read mono " + path);
  std::vector<float> input(static_cast<std::size_t>(info.frames));
  sf_readf_float(file, input.data(), info.frames);
  sf_close(file);
  // Windowed-sinc resampling to 44.1 kHz (the input is band-limited below its own Nyquist).
  const double ratio = info.samplerate / kRate;
  const long out_count = static_cast<long>(input.size() / ratio);
  std::vector<float> out(static_cast<std::size_t>(out_count));
  constexpr int kHalf = 16;
  const double cutoff = std::min(1.0, 1.0 / ratio);
  for (long n = 0; n < out_count; ++n) {
    const double t = n * ratio;
    const long centre = static_cast<long>(std::floor(t));
    double sum = 0;
    for (long i = centre - kHalf + 1; i <= centre + kHalf; ++i) {
      if (i < 0 || i >= static_cast<long>(input.size())) continue;
      const double x = t - i;
      const double sinc = std::abs(x) < 1e-9 ? 1.0 : std::sin(M_PI * x * cutoff) / (M_PI * x * cutoff);
      const double window = 0.5 + 0.5 * std::cos(M_PI * x / kHalf);
      sum += input[static_cast<std::size_t>(i)] * sinc * window * cutoff;
    }
    out[static_cast<std::size_t>(n)] = static_cast<float>(sum);
  }
  scaleTo(out, rms);
  return out;
}

double loopedRms(const std::vector<float>& signal, long first, int count) {
  double sum = 0;
  const long size = static_cast<long>(signal.size());
  for (int n = 0; n < count; ++n) {
    const float s = signal[static_cast<std::size_t>(((first + n) % size + size) % size)];
    sum += static_cast<double>(s) * s;
  }
  return std::sqrt(sum / count);
}

KemarEars::KemarEars() {
  const char* path = HrirSet::kKemarPath;
  SF_INFO info{};
  SNDFILE* file = sf_open(path, SFM_READ, &info);
  if (file == nullptr || info.channels != 720 || info.samplerate != 44100)
    throw std::runtime_error(std::string("cannot read the 720-channel KEMAR responses ") + path);
  std::vector<float> interleaved(static_cast<std::size_t>(info.frames * info.channels));
  sf_readf_float(file, interleaved.data(), info.frames);
  sf_close(file);
  left_.assign(360, std::vector<float>(static_cast<std::size_t>(info.frames)));
  right_ = left_;
  for (long n = 0; n < info.frames; ++n)
    for (int a = 0; a < 360; ++a) {
      left_[static_cast<std::size_t>(a)][static_cast<std::size_t>(n)] = interleaved[static_cast<std::size_t>(n * 720 + 2 * a)];
      right_[static_cast<std::size_t>(a)][static_cast<std::size_t>(n)] =
          interleaved[static_cast<std::size_t>(n * 720 + 2 * a + 1)];
    }
}

void KemarEars::render(const std::vector<PlacedSound>& sounds, std::vector<float>& left, std::vector<float>& right,
                       int samples, float noise_rms, uint64_t noise_seed) const {
  left.assign(static_cast<std::size_t>(samples), 0.0f);
  right.assign(static_cast<std::size_t>(samples), 0.0f);
  for (const PlacedSound& sound : sounds) {
    const int azimuth = static_cast<int>(((std::lround(sound.azimuth_deg) % 360) + 360) % 360);
    const auto& hl = left_[static_cast<std::size_t>(azimuth)];
    const auto& hr = right_[static_cast<std::size_t>(azimuth)];
    const long size = static_cast<long>(sound.signal->size());
    for (int n = 0; n < samples; ++n) {
      double sl = 0, sr = 0;
      for (std::size_t k = 0; k < hl.size(); ++k) {
        const long i = ((sound.offset + n - static_cast<long>(k)) % size + size) % size;
        const float x = (*sound.signal)[static_cast<std::size_t>(i)];
        sl += hl[k] * x;
        sr += hr[k] * x;
      }
      left[static_cast<std::size_t>(n)] += static_cast<float>(sound.gain * sl);
      right[static_cast<std::size_t>(n)] += static_cast<float>(sound.gain * sr);
    }
  }
  std::mt19937_64 random(noise_seed);
  std::normal_distribution<float> gauss(0, noise_rms);
  for (int n = 0; n < samples; ++n) {
    left[static_cast<std::size_t>(n)] += gauss(random);
    right[static_cast<std::size_t>(n)] += gauss(random);
  }
}

}  // namespace beft::hearing::trials
