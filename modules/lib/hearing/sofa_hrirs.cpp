#include "lib/hearing/sofa_hrirs.hpp"

#include <mysofa.h>

#include <cmath>
#include <fstream>
#include <memory>

namespace beft::hearing {

namespace {

std::string mysofaProblem(int error) {
  switch (error) {
    case MYSOFA_READ_ERROR: return "cannot be read";
    case MYSOFA_INVALID_FORMAT: return "is not a SOFA (HDF5) file";
    case MYSOFA_UNSUPPORTED_FORMAT: return "uses a SOFA convention libmysofa does not support";
    case MYSOFA_NO_MEMORY: return "does not fit in memory";
    default: return "is not usable (libmysofa error " + std::to_string(error) + ")";
  }
}

double energy(const std::vector<float>& samples) {
  double sum = 0;
  for (float s : samples) sum += static_cast<double>(s) * s;
  return sum;
}

// A delay the file stores apart from the responses, put back in front of them.
void prependDelay(std::vector<float>& response, float delay_s, double sample_rate) {
  const long samples = std::lround(static_cast<double>(delay_s) * sample_rate);
  if (samples > 0 && samples < 1 << 16) response.insert(response.begin(), static_cast<std::size_t>(samples), 0.0f);
}

}  // namespace

HorizontalHrirs loadSofaHorizontal(const std::string& path, double sample_rate) {
  if (!(sample_rate > 0)) throw SofaError("SOFA responses need a sample rate > 0");
  if (!std::ifstream(path).good())
    throw SofaError("cannot open the SOFA file '" + path + "' (the MIT KEMAR responses come with libmysofa1)");
  int filter_length = 0, error = 0;
  // mysofa_open resamples to sample_rate and scales every response alike (so interaural differences stay).
  std::unique_ptr<MYSOFA_EASY, void (*)(MYSOFA_EASY*)> sofa(
      mysofa_open(path.c_str(), static_cast<float>(sample_rate), &filter_length, &error), mysofa_close);
  if (!sofa || error != MYSOFA_OK) throw SofaError("the SOFA file '" + path + "' " + mysofaProblem(error));
  if (filter_length <= 0 || filter_length > 1 << 20)
    throw SofaError("the SOFA file '" + path + "' has responses of " + std::to_string(filter_length) + " samples");

  HorizontalHrirs hrirs;
  hrirs.sample_rate = sample_rate;
  hrirs.left.resize(360);
  hrirs.right.resize(360);
  for (int azimuth = 0; azimuth < 360; ++azimuth) {
    const double a = azimuth * M_PI / 180;
    auto& left = hrirs.left[static_cast<std::size_t>(azimuth)];
    auto& right = hrirs.right[static_cast<std::size_t>(azimuth)];
    left.assign(static_cast<std::size_t>(filter_length), 0.0f);
    right.assign(static_cast<std::size_t>(filter_length), 0.0f);
    float delay_left = 0, delay_right = 0;
    // SOFA's cartesian frame: x front, y left, z up; libmysofa finds the nearest measurements and interpolates.
    mysofa_getfilter_float(sofa.get(), static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f,
                           left.data(), right.data(), &delay_left, &delay_right);
    prependDelay(left, delay_left, sample_rate);
    prependDelay(right, delay_right, sample_rate);
    for (float v : left)
      if (!std::isfinite(v)) throw SofaError("the SOFA file '" + path + "' has responses that are not finite");
    for (float v : right)
      if (!std::isfinite(v)) throw SofaError("the SOFA file '" + path + "' has responses that are not finite");
  }
  if (!(energy(hrirs.left[90]) > 2 * energy(hrirs.right[90])) || !(energy(hrirs.right[270]) > 2 * energy(hrirs.left[270])))
    throw SofaError("the SOFA file '" + path + "' does not put +90 degrees azimuth on the left (its source there is "
                    "not clearly louder at the left ear)");
  return hrirs;
}

}  // namespace beft::hearing
