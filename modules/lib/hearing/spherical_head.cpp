// HrirSet::sphericalHead: Brown, C. P. and Duda, R. O. (1998), "A structural
// model for binaural sound synthesis", IEEE Trans. Speech Audio Process. 6(5),
// the head model of its section III.A, sampled as impulse responses.
#include <cmath>
#include <vector>

#include "lib/hearing/hrir_set.hpp"

namespace beft::hearing {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHeadRadius = 0.0875;     // a [m]
constexpr double kSpeedOfSound = 343.0;    // c [m/s]
constexpr double kEarAzimuthDeg = 100.0;   // the paper's ears: 100 degrees from the nose, each side
constexpr double kAlphaMin = 0.1;          // head shadow's strongest high-frequency cut (-20 dB)
constexpr double kThetaMinDeg = 150.0;     // incidence angle where the cut is strongest
constexpr int kDirections = 360;
constexpr int kSincHalfWidth = 16;         // fractional-delay kernel: 16 samples each side
constexpr double kLeadIn = 24;             // samples before the earliest arrival (room for the kernel)

// Angle between the source and the ear's axis [rad], in [0, pi].
double incidence(double source_deg, double ear_deg) {
  double difference = std::fmod(std::fabs(source_deg - ear_deg), 360.0);
  if (difference > 180) difference = 360 - difference;
  return difference * kPi / 180;
}

// The paper's eq. (2)/(3): a one-pole/one-zero filter whose high-frequency
// gain alpha(theta) runs from 2 (+6 dB, facing the ear) to alpha_min
// (shadowed), cross-over at omega_0 = c / a:
//   H(s) = (1 + alpha s / (2 omega_0)) / (1 + s / (2 omega_0)),
// made discrete by the bilinear transform (omega_0 is ~620 Hz, so its
// frequency warping is negligible).
std::vector<double> headShadowResponse(double theta, double sample_rate, int taps) {
  const double alpha = (1 + kAlphaMin / 2) + (1 - kAlphaMin / 2) * std::cos(theta / (kThetaMinDeg * kPi / 180) * kPi);
  const double omega0 = kSpeedOfSound / kHeadRadius;
  const double k = sample_rate / omega0;  // 2 fs / (2 omega_0)
  const double b0 = (1 + alpha * k) / (1 + k), b1 = (1 - alpha * k) / (1 + k), a1 = (1 - k) / (1 + k);
  std::vector<double> h(taps);
  double previous_in = 0, previous_out = 0;
  for (int n = 0; n < taps; ++n) {
    const double in = n == 0 ? 1.0 : 0.0;
    const double out = b0 * in + b1 * previous_in - a1 * previous_out;
    h[n] = out;
    previous_in = in;
    previous_out = out;
  }
  return h;
}

// The paper's eq. (4), Woodworth's delay relative to the head centre [s]:
// -a/c cos(theta) on the lit side, a/c (theta - pi/2) round the back.
double woodworthDelay(double theta) {
  return theta < kPi / 2 ? -kHeadRadius / kSpeedOfSound * std::cos(theta)
                         : kHeadRadius / kSpeedOfSound * (theta - kPi / 2);
}

// A Blackman-windowed sinc centred on `delay`, normalised to unit DC gain.
std::vector<double> fractionalDelayKernel(double delay, int& first_tap) {
  first_tap = static_cast<int>(std::floor(delay)) - kSincHalfWidth;
  std::vector<double> kernel(2 * kSincHalfWidth + 2);
  double sum = 0;
  for (std::size_t i = 0; i < kernel.size(); ++i) {
    const double x = first_tap + static_cast<double>(i) - delay;  // in (-17, 17)
    const double span = kSincHalfWidth + 1.0;
    if (std::fabs(x) >= span) continue;
    const double sinc = x == 0 ? 1.0 : std::sin(kPi * x) / (kPi * x);
    const double phase = kPi * (x + span) / span;  // 0 .. 2 pi over the window
    const double window = 0.42 - 0.5 * std::cos(phase) + 0.08 * std::cos(2 * phase);
    kernel[i] = sinc * window;
    sum += kernel[i];
  }
  for (double& value : kernel) value /= sum;
  return kernel;
}

}  // namespace

HrirSet HrirSet::sphericalHead(double sample_rate) {
  if (!(sample_rate >= 8000 && sample_rate <= 384000)) {
    throw HrirError("spherical-head HRIRs: sample rate " + std::to_string(sample_rate) +
                    " Hz is outside 8000 to 384000 Hz");
  }
  const double head_delay = kHeadRadius / kSpeedOfSound * sample_rate;  // a/c in samples
  // Long enough for the latest arrival (round the back: a/c (1 + pi/2)
  // after the lead-in) plus the kernel and the shadow filter's decay to 1e-9
  // (its pole is (k - 1) / (k + 1), k = fs a / c): 192 taps at 44.1 kHz.
  const double k = sample_rate * kHeadRadius / kSpeedOfSound;
  const double latest = kLeadIn + head_delay * (1 + kPi / 2) + kSincHalfWidth + 1;
  const int taps = 64 * static_cast<int>(std::ceil((latest + std::log(1e-9) / std::log((k - 1) / (k + 1))) / 64));
  std::vector<float> responses(static_cast<std::size_t>(2) * kDirections * taps, 0.0f);
  for (int direction = 0; direction < kDirections; ++direction) {
    const double azimuth = direction * 360.0 / kDirections;
    for (const Ear ear : {Ear::Left, Ear::Right}) {
      const double theta = incidence(azimuth, ear == Ear::Left ? kEarAzimuthDeg : -kEarAzimuthDeg);
      const std::vector<double> shadow = headShadowResponse(theta, sample_rate, taps);
      int first_tap = 0;
      const std::vector<double> kernel =
          fractionalDelayKernel(kLeadIn + head_delay + woodworthDelay(theta) * sample_rate, first_tap);
      float* out = responses.data() + (static_cast<std::size_t>(2) * direction + static_cast<int>(ear)) * taps;
      for (int n = 0; n < taps; ++n) {
        double sum = 0;
        for (std::size_t i = 0; i < kernel.size(); ++i) {
          const int source_tap = n - first_tap - static_cast<int>(i);
          if (source_tap >= 0 && source_tap < taps) sum += kernel[i] * shadow[source_tap];
        }
        out[n] = static_cast<float>(sum);
      }
    }
  }
  return HrirSet("spherical-head HRIRs (Brown & Duda 1998, a = 8.75 cm, ears at +-100 deg)", sample_rate, taps,
                 kDirections, std::move(responses), kLeadIn + head_delay);
}

}  // namespace beft::hearing
