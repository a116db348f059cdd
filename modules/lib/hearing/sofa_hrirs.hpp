// Head-related impulse responses of the horizontal plane read from a SOFA
// file (AES69) through libmysofa: one pair per whole degree of azimuth, at
// elevation 0, resampled to the rate asked for.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace beft::hearing {

// The MIT KEMAR measurements (Gardner & Martin 1994) as Debian's libmysofa ships them.
inline constexpr const char* kMitKemarSofa = "/usr/share/libmysofa/MIT_KEMAR_normal_pinna.sofa";

struct HorizontalHrirs {
  double sample_rate = 0;                       // [Hz]
  std::vector<std::vector<float>> left, right;  // [azimuth in whole degrees, 0..359, CCW, 0 = front, 90 = left]
};

class SofaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws SofaError if the file is missing or unreadable, or if its responses
// do not put +90 degrees on the left (louder at the left ear): libmysofa's
// coordinates are SOFA's (x to the front, y to the left, z up), and a file
// that does not follow them would turn every template the wrong way round.
HorizontalHrirs loadSofaHorizontal(const std::string& path, double sample_rate);

}  // namespace beft::hearing
