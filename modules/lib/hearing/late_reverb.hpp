// The diffuse late tail of a room: a pair of decaying noises, one per ear,
// whose interaural coherence is that of a diffuse field at the head the
// renderer uses (computed from its HRIR set, not two independent noises),
// whose spectrum is the head's diffuse-field response, and whose energy
// decays by 60 dB in T60. And what is measured on a rendered impulse
// response: Schroeder's T60 and the direct-to-reverberant ratio.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "lib/hearing/fft_convolver.hpp"
#include "lib/hearing/hrir_set.hpp"

namespace beft::hearing {

// The interaural coherence of a diffuse field and the diffuse-field power
// of each ear at bins k * sample_rate / fft_size, from the directions of an
// HRIR set, all weighted alike (the set is horizontal, so this is the
// coherence of a field diffuse in the horizontal plane):
// gamma(f) = Re sum_d H_L(d,f) H_R*(d,f) / sqrt(sum_d |H_L|^2 sum_d |H_R|^2)
// (Jacobsen and Roisin 2000, JASA 108(1); Borss and Martin 2009, "An
// improved parametric model for perception-based design of virtual
// acoustics", AES 35th conf.).
struct DiffuseField {
  std::vector<double> coherence;               // per bin, in [-1, 1]
  std::vector<double> power_left, power_right; // per bin, mean over directions of |H|^2
};
DiffuseField diffuseField(const HrirSet& hrirs, int fft_size);

class LateReverb {
 public:
  // T60 in (0, 10] s; onset: the tail's first sample comes this long after
  // the direct sound (the mixing time; Polack's sqrt(V) ms by default in
  // RoomModel), with a 5 ms raised-cosine fade-in. Two white Gaussian
  // noises n1, n2 (seeded) mixed per FFT bin as L = g_L (a n1 + b n2),
  // R = g_R (a n1 - b n2), a = sqrt((1 + gamma) / 2), b = sqrt((1 - gamma) / 2),
  // which gives L and R the coherence a^2 - b^2 = gamma (Habets, Cohen and
  // Gannot 2008, JASA 124(5), for two sensors), g the diffuse-field
  // magnitudes; then the envelope exp(-3 ln 10 (t + onset) / T60). Scaled so
  // that the tail's energy per ear is what a diffuse field decaying from
  // t = 0 with unit energy (heard through the diffuse-field response of
  // mean HRIR energy) has left after the onset: exp(-6 ln 10 onset / T60)
  // times the set's mean HRIR energy. Long enough for the envelope to fall
  // 60 dB from t = 0.
  LateReverb(const HrirSet& hrirs, double t60_s, double onset_s, double sample_rate, uint64_t seed);

  double t60() const { return t60_s_; }
  double onset() const { return onset_s_; }
  int length() const { return static_cast<int>(left_.size()); }
  const std::vector<float>& left() const { return left_; }
  const std::vector<float>& right() const { return right_; }

  // The two responses' spectra at an FFT size (made once per size, shared).
  const std::pair<Spectrum, Spectrum>& spectra(const RealFft& fft) const;

 private:
  double t60_s_, onset_s_;
  std::vector<float> left_, right_;
  mutable std::mutex mutex_;
  mutable std::map<int, std::pair<Spectrum, Spectrum>> spectra_;
};

// Schroeder's backward integration (1965, JASA 37) of an impulse response,
// EDC(t) = sum_{n >= t} h^2, in dB re its start, and the T60 of a straight
// line fitted (least squares) to it between from_db and to_db (T30 by
// default: -5 to -35 dB), extrapolated to 60 dB. 0 if the EDC never reaches to_db.
double schroederT60(const std::vector<float>& ir, double sample_rate, double from_db = -5, double to_db = -35);
// The same over the sum of two ears' EDCs.
double schroederT60(const std::vector<float>& left, const std::vector<float>& right, double sample_rate,
                    double from_db = -5, double to_db = -35);

// Direct-to-reverberant ratio [dB] of an impulse response pair: the energy
// up to `direct_end` samples over the energy after it (both ears summed).
double directToReverberantDb(const std::vector<float>& left, const std::vector<float>& right, int direct_end);

}  // namespace beft::hearing
