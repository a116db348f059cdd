// A distribution over head-relative azimuth in whole degrees (0..359, CCW,
// 0 = the nose, 90 = the left ear), its peaks, and the front-back mirror
// image that interaural cues cannot tell apart from the true direction.
#pragma once

#include <array>
#include <vector>

namespace beft::hearing {

// Angle in [0, 360).
double wrapDegrees(double degrees);
// Smallest angle between two directions, in [0, 180].
double angularDistance(double a_deg, double b_deg);
// The direction with the same interaural cues on a symmetric head: reflected
// about the interaural axis (a and 180 - a).
double frontBackMirror(double azimuth_deg);

struct AzimuthPeak {
  double azimuth_deg = 0;  // refined between whole degrees
  double weight = 0;       // share of the posterior within half the peaks' minimum separation of it
};

class AzimuthPosterior {
 public:
  static constexpr int kBins = 360;

  AzimuthPosterior();  // flat: nothing known
  // Normalised to sum 1; values must be finite and >= 0 (all zero gives flat).
  explicit AzimuthPosterior(const std::array<double, kBins>& values);

  double operator[](int azimuth_deg) const { return p_[static_cast<std::size_t>(azimuth_deg)]; }
  double at(double azimuth_deg) const;  // linear between whole degrees
  const std::array<double, kBins>& values() const { return p_; }
  bool isFlat() const;

  // Local maxima, heaviest first (by weight, not height: a source heard only
  // at low frequencies gives a broad peak, yet as much evidence), each at
  // least min_separation_deg from every heavier one kept and weighing at
  // least min_relative_weight of the heaviest. A flat posterior has none.
  std::vector<AzimuthPeak> peaks(double min_separation_deg = 20, double min_relative_weight = 0.1) const;
  // The highest value's azimuth (refined between whole degrees); 0 if flat.
  double mostLikely() const;
  // Probability within +-half_width_deg of a direction.
  double massNear(double azimuth_deg, double half_width_deg) const;
  // The same distribution in a frame turned by turn_deg CCW: what was at a is at a - turn_deg.
  AzimuthPosterior inTurnedFrame(double turn_deg) const;

 private:
  std::array<double, kBins> p_;
};

// True if the most likely direction's front-back mirror holds at least
// min_ratio of the probability near the most likely direction itself (both
// within +-half_width_deg), and the two are far enough apart to be told
// apart (near the interaural axis they are the same direction). A flat
// posterior is not ambiguous (it has no direction at all).
bool isFrontBackAmbiguous(const AzimuthPosterior& posterior, double min_ratio = 0.3, double half_width_deg = 10);

// The turn a listener makes to resolve front and back: 20 degrees moves the
// two mirror images 40 degrees apart, more than twice the width of a
// posterior peak even beside the head, where the interaural cues change
// least with azimuth (about +-10 degrees there, +-3 in front), so blocks
// pooled across the turn (BlockLocaliser::localise(blocks)) agree on the
// true direction and split their mirror images (Wallach 1940); the head turns it
// in about 0.1 s at 180 deg/s and it stays well within the +-85 degrees pan.
inline constexpr double kDefaultResolvingTurnDeg = 20;

}  // namespace beft::hearing
