#include "lib/hearing/late_reverb.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <stdexcept>
#include <string>

namespace beft::hearing {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLn10 = 2.302585092994046;
constexpr double kFadeInSeconds = 0.005;

// The energy decay curve in dB re its start (-inf-free: floored at -300 dB).
std::vector<double> decayCurveDb(const std::vector<double>& energy) {
  std::vector<double> edc(energy.size());
  double sum = 0;
  for (std::size_t i = energy.size(); i-- > 0;) {
    sum += energy[i];
    edc[i] = sum;
  }
  const double start = edc.empty() ? 0 : edc[0];
  for (double& value : edc) value = start > 0 && value > 0 ? 10 * std::log10(value / start) : -300;
  return edc;
}

double fitT60(const std::vector<double>& edc_db, double sample_rate, double from_db, double to_db) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  bool reached = false;
  for (std::size_t i = 0; i < edc_db.size(); ++i) {
    if (edc_db[i] > from_db) continue;
    if (edc_db[i] < to_db) {
      reached = true;
      break;
    }
    const double t = i / sample_rate;
    n += 1;
    sx += t;
    sy += edc_db[i];
    sxx += t * t;
    sxy += t * edc_db[i];
  }
  if (!reached || n < 2) return 0;
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);  // dB per second
  return slope < 0 ? -60 / slope : 0;
}

// Linear interpolation of a per-bin table made at another FFT size.
double atFraction(const std::vector<double>& table, double fraction) {
  const double position = std::clamp(fraction, 0.0, 1.0) * (table.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, table.size() - 1);
  const double w = position - below;
  return (1 - w) * table[below] + w * table[above];
}

}  // namespace

DiffuseField diffuseField(const HrirSet& hrirs, int fft_size) {
  const RealFft fft(fft_size);
  const int bins = fft.bins();
  std::vector<std::complex<double>> cross(static_cast<std::size_t>(bins));
  DiffuseField field;
  field.power_left.assign(static_cast<std::size_t>(bins), 0.0);
  field.power_right.assign(static_cast<std::size_t>(bins), 0.0);
  Samples scratch;
  Spectrum left, right;
  const int length = std::min(hrirs.length(), fft_size);
  for (int d = 0; d < hrirs.directionCount(); ++d) {
    fft.forward(hrirs.response(d, Ear::Left), length, scratch, left);
    fft.forward(hrirs.response(d, Ear::Right), length, scratch, right);
    for (int k = 0; k < bins; ++k) {
      const auto i = static_cast<std::size_t>(k);
      const std::complex<double> l(left[i]), r(right[i]);
      cross[i] += l * std::conj(r);
      field.power_left[i] += std::norm(l);
      field.power_right[i] += std::norm(r);
    }
  }
  field.coherence.resize(static_cast<std::size_t>(bins));
  for (std::size_t i = 0; i < cross.size(); ++i) {
    const double norm = std::sqrt(field.power_left[i] * field.power_right[i]);
    field.coherence[i] = norm > 0 ? std::clamp(cross[i].real() / norm, -1.0, 1.0) : 0.0;
    field.power_left[i] /= hrirs.directionCount();
    field.power_right[i] /= hrirs.directionCount();
  }
  return field;
}

LateReverb::LateReverb(const HrirSet& hrirs, double t60_s, double onset_s, double sample_rate, uint64_t seed)
    : t60_s_(t60_s), onset_s_(onset_s) {
  if (!(t60_s > 0 && t60_s <= 10) || !(onset_s >= 0 && onset_s < t60_s) || !(sample_rate > 0))
    throw std::invalid_argument("LateReverb: T60 " + std::to_string(t60_s) + " s must be in (0, 10], the onset " +
                                std::to_string(onset_s) + " s in [0, T60)");
  const int length = std::max(16, static_cast<int>(std::ceil((t60_s - onset_s) * sample_rate)));
  const RealFft fft(fastFftSize(length));
  const DiffuseField field = diffuseField(hrirs, 1024);

  std::mt19937_64 random(seed);
  std::normal_distribution<float> gauss(0, 1);
  std::vector<float> noise[2];
  Spectrum spectra[2];
  Samples scratch;
  for (int i = 0; i < 2; ++i) {
    noise[i].resize(static_cast<std::size_t>(fft.size()));
    for (float& s : noise[i]) s = gauss(random);
    fft.forward(noise[i].data(), fft.size(), scratch, spectra[i]);
  }
  Spectrum mixed[2];
  for (Spectrum& m : mixed) m.resize(fft.bins());
  for (int k = 0; k < fft.bins(); ++k) {
    const double fraction = static_cast<double>(k) / (fft.bins() - 1);
    const double gamma = atFraction(field.coherence, fraction);
    const double a = std::sqrt((1 + gamma) / 2), b = std::sqrt((1 - gamma) / 2);
    const double gl = std::sqrt(atFraction(field.power_left, fraction));
    const double gr = std::sqrt(atFraction(field.power_right, fraction));
    const auto i = static_cast<std::size_t>(k);
    const std::complex<float> n1 = spectra[0][i], n2 = spectra[1][i];
    mixed[0][i] = static_cast<float>(gl) * (static_cast<float>(a) * n1 + static_cast<float>(b) * n2);
    mixed[1][i] = static_cast<float>(gr) * (static_cast<float>(a) * n1 - static_cast<float>(b) * n2);
  }
  double mean_hrir_energy = 0;
  for (int d = 0; d < hrirs.directionCount(); ++d)
    for (Ear ear : {Ear::Left, Ear::Right})
      for (int t = 0; t < hrirs.length(); ++t) mean_hrir_energy += std::pow(hrirs.response(d, ear)[t], 2);
  mean_hrir_energy /= 2.0 * hrirs.directionCount();
  // Energy of exp(-6 ln10 t / T60) from the onset on, per second of unit density.
  const double decay_rate = 6 * kLn10 / t60_s;  // energy: e^(-decay_rate t)
  const double target = mean_hrir_energy * std::exp(-decay_rate * onset_s);
  std::vector<float>* outputs[2] = {&left_, &right_};
  for (int ear = 0; ear < 2; ++ear) {
    Samples time;
    fft.inverse(mixed[ear], time);
    std::vector<float>& out = *outputs[ear];
    out.resize(static_cast<std::size_t>(length));
    for (int n = 0; n < length; ++n) {
      const double t = n / sample_rate;
      const double fade = t < kFadeInSeconds ? 0.5 - 0.5 * std::cos(kPi * t / kFadeInSeconds) : 1.0;
      out[static_cast<std::size_t>(n)] = static_cast<float>(time[n] * fade * std::exp(-0.5 * decay_rate * (t + onset_s)));
    }
  }
  // One scale for both ears (keeps their balance), the mean energy on target.
  double energy = 0;
  for (const std::vector<float>* out : outputs)
    for (float s : *out) energy += static_cast<double>(s) * s;
  const float scale = static_cast<float>(std::sqrt(target / std::max(energy / 2, 1e-300)));
  for (std::vector<float>* out : outputs)
    for (float& s : *out) s *= scale;
}

const std::pair<Spectrum, Spectrum>& LateReverb::spectra(const RealFft& fft) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto found = spectra_.find(fft.size());
  if (found != spectra_.end()) return found->second;
  if (fft.size() < length()) throw std::invalid_argument("LateReverb: FFT shorter than the tail");
  std::pair<Spectrum, Spectrum> pair;
  Samples scratch;
  fft.forward(left_.data(), length(), scratch, pair.first);
  fft.forward(right_.data(), length(), scratch, pair.second);
  return spectra_.emplace(fft.size(), std::move(pair)).first->second;
}

double schroederT60(const std::vector<float>& ir, double sample_rate, double from_db, double to_db) {
  std::vector<double> energy(ir.size());
  for (std::size_t i = 0; i < ir.size(); ++i) energy[i] = static_cast<double>(ir[i]) * ir[i];
  return fitT60(decayCurveDb(energy), sample_rate, from_db, to_db);
}

double schroederT60(const std::vector<float>& left, const std::vector<float>& right, double sample_rate,
                    double from_db, double to_db) {
  std::vector<double> energy(std::min(left.size(), right.size()));
  for (std::size_t i = 0; i < energy.size(); ++i)
    energy[i] = static_cast<double>(left[i]) * left[i] + static_cast<double>(right[i]) * right[i];
  return fitT60(decayCurveDb(energy), sample_rate, from_db, to_db);
}

double directToReverberantDb(const std::vector<float>& left, const std::vector<float>& right, int direct_end) {
  double direct = 0, reverberant = 0;
  const std::size_t count = std::min(left.size(), right.size());
  for (std::size_t i = 0; i < count; ++i) {
    const double e = static_cast<double>(left[i]) * left[i] + static_cast<double>(right[i]) * right[i];
    (static_cast<int>(i) < direct_end ? direct : reverberant) += e;
  }
  return 10 * std::log10(std::max(direct, 1e-300) / std::max(reverberant, 1e-300));
}

}  // namespace beft::hearing
