#include "lib/hearing/binaural_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <utility>

#include "lib/hearing/fft_convolver.hpp"
#include "lib/hearing/looped_signal.hpp"
#include "lib/hearing/sensor_noise.hpp"
#include "lib/hearing/source_reading.hpp"

namespace beft::hearing {

namespace {

using detail::progressAt;
using detail::readMoving;
using detail::readStill;
using detail::SourceView;
using detail::kMaxChunk;
using detail::kPi;

// Absolute sample indices beyond this lose precision as doubles.
constexpr int64_t kMaxAbsoluteSample = int64_t{1} << 52;

// Buffers reused from call to call on the same thread.
struct Scratch {
  Samples segment, padded, time;
  Spectrum source, lowpass, filter;
  Spectrum sums[2][2];    // [pose][ear]
  Samples outputs[2][2];  // [pose][ear]
  std::vector<float> hrir_left, hrir_right;
  std::vector<SourceView> views[2];
};

Scratch& threadScratch() {
  thread_local Scratch scratch;
  return scratch;
}

bool finite(const Eigen::Vector3d& v) { return v.allFinite(); }

void refuse(const std::string& what) { throw std::invalid_argument("BinauralRenderer: " + what); }

void checkRequest(const BlockRequest& request, double sample_rate) {
  const double max_samples = BinauralRenderer::kMaxBlockSeconds * sample_rate;
  if (request.num_samples < 0 || request.num_samples > max_samples) {
    refuse("num_samples " + std::to_string(request.num_samples) + " is outside 0 to " +
           std::to_string(static_cast<int64_t>(max_samples)) + " (" +
           std::to_string(static_cast<int>(BinauralRenderer::kMaxBlockSeconds)) + " s)");
  }
  if (request.first_sample < -kMaxAbsoluteSample || request.first_sample > kMaxAbsoluteSample) {
    refuse("first_sample " + std::to_string(request.first_sample) + " is beyond +-2^52");
  }
  for (const auto& [pose, name] : {std::pair<const HeadPose*, const char*>{&request.previous, "previous"},
                                   std::pair<const HeadPose*, const char*>{&request.current, "current"}}) {
    if (!finite(pose->centre) || !std::isfinite(pose->yaw_deg)) refuse(std::string(name) + " head pose is not finite");
  }
  if (!std::isfinite(request.noise_rms) || request.noise_rms < 0) {
    refuse("noise_rms " + std::to_string(request.noise_rms) + " is not a finite value >= 0");
  }
  for (std::size_t i = 0; i < request.sources.size(); ++i) {
    const RenderedSource& source = request.sources[i];
    const std::string which = "source " + std::to_string(i) + ": ";
    if (source.signal == nullptr || source.signal->samples.empty()) refuse(which + "has no signal samples");
    if (!finite(source.position)) refuse(which + "position is not finite");
    if (!std::isfinite(source.level) || source.level < 0) {
      refuse(which + "level " + std::to_string(source.level) + " is not a finite value >= 0");
    }
    if (!(source.occlusion >= 0 && source.occlusion <= 1)) {
      refuse(which + "occlusion " + std::to_string(source.occlusion) + " is outside [0, 1]");
    }
  }
}

bool samePose(const HeadPose& a, const HeadPose& b) { return a.centre == b.centre && a.yaw_deg == b.yaw_deg; }

// The sources' azimuth, gain and delay for each of the first `poses` poses
// (previous, current).
void viewSources(const BlockRequest& request, int poses, double sample_rate, Scratch& s) {
  const HeadPose* pose_of[2] = {&request.previous, &request.current};
  const std::size_t source_count = request.sources.size();
  for (int p = 0; p < poses; ++p) {
    s.views[p].resize(source_count);
    for (std::size_t i = 0; i < source_count; ++i) {
      const RenderedSource& source = request.sources[i];
      const double distance = std::max(BinauralRenderer::kMinDistance, (source.position - pose_of[p]->centre).norm());
      s.views[p][i] = {BinauralRenderer::headAzimuthDeg(*pose_of[p], source.position), source.level / distance,
                       distance / BinauralRenderer::kSpeedOfSound * sample_rate};
    }
  }
}

}  // namespace

BinauralRenderer::BinauralRenderer(HrirSet hrirs, double sample_rate, OcclusionModel occlusion)
    : hrirs_(std::move(hrirs)), sample_rate_(sample_rate), occlusion_(occlusion) {
  if (!(sample_rate_ > 0) || !std::isfinite(sample_rate_)) {
    throw std::invalid_argument("BinauralRenderer: sample rate " + std::to_string(sample_rate_) + " Hz is not positive");
  }
  if (std::fabs(hrirs_.sampleRate() - sample_rate_) > 1e-6) {
    throw std::invalid_argument("BinauralRenderer: the HRIR set (" + hrirs_.name() + ") is at " +
                                std::to_string(hrirs_.sampleRate()) + " Hz, the renderer at " +
                                std::to_string(sample_rate_) + " Hz; resample one of them");
  }
  occlusion_.taps = std::max(1, occlusion_.taps | 1);
  filter_length_ = hrirs_.length() + occlusion_.taps - 1;
  read_advance_ = hrirs_.centreDelaySamples() + (occlusion_.taps - 1) / 2.0;
}

double BinauralRenderer::headAzimuthDeg(const HeadPose& pose, const Eigen::Vector3d& point) {
  const Eigen::Vector3d relative = point - pose.centre;
  double azimuth = std::atan2(relative.y(), relative.x()) * 180 / kPi - pose.yaw_deg;
  azimuth = std::fmod(azimuth, 360.0);
  if (azimuth > 180) azimuth -= 360;
  if (azimuth <= -180) azimuth += 360;
  return azimuth;
}

StereoBlock BinauralRenderer::render(const BlockRequest& request) const {
  StereoBlock out;
  render(request, out);
  return out;
}

void BinauralRenderer::render(const BlockRequest& request, StereoBlock& out) const {
  checkRequest(request, sample_rate_);
  const int total = request.num_samples;
  out.left.assign(total, 0.0f);
  out.right.assign(total, 0.0f);
  if (total == 0) return;

  Scratch& s = threadScratch();
  const bool turning = !samePose(request.previous, request.current);
  viewSources(request, turning ? 2 : 1, sample_rate_, s);
  s.hrir_left.resize(hrirs_.length());
  s.hrir_right.resize(hrirs_.length());
  if (request.direct_sound) {
    for (int chunk_start = 0; chunk_start < total; chunk_start += kMaxChunk) {
      renderChunk(request, turning, chunk_start, std::min(kMaxChunk, total - chunk_start), out);
    }
  }
  if (request.room != nullptr) addRoom(request, turning, out);

  addSensorNoise(request.noise_seed, request.first_sample, total, request.noise_rms, out.left.data(),
                 out.right.data());
}

// One chunk of the block by overlap-save: each source as it arrives at the
// head centre, low-passed by its occlusion and filtered by the HRIRs of each
// pose; then the poses blended.
void BinauralRenderer::renderChunk(const BlockRequest& request, bool turning, int chunk_start, int chunk,
                                   StereoBlock& out) const {
  Scratch& s = threadScratch();
  const int poses = turning ? 2 : 1;
  const int hrir_length = hrirs_.length();
  const int history = filter_length_ - 1;
  const int total = request.num_samples;
  const int64_t first = request.first_sample;
  const int segment_length = chunk + history;
  const int64_t segment_first = first + chunk_start - history;
  const RealFft fft(fastFftSize(segment_length));
  const int bins = fft.bins();
  for (int p = 0; p < poses; ++p)
    for (auto& sum : s.sums[p]) {
      sum.resize(bins);
      std::fill(sum.data(), sum.data() + bins, std::complex<float>(0, 0));
    }
  s.segment.resize(segment_length);

  for (std::size_t i = 0; i < request.sources.size(); ++i) {
    const RenderedSource& source = request.sources[i];
    const std::vector<float>& signal = source.signal->samples;
    // The source as it arrives at the head centre, over the chunk and the
    // history the filters need.
    if (!turning) {
      readStill(signal, s.views[0][i], read_advance_, segment_first, segment_length, s.segment.data());
    } else {
      readMoving(signal, s.views[0][i], s.views[1][i], read_advance_, segment_first, segment_length, first, total,
                 s.segment.data());
    }
    fft.forward(s.segment.data(), segment_length, s.padded, s.source);
    const std::vector<float> lowpass = occlusionFilter(source.occlusion, sample_rate_, occlusion_);
    fft.forward(lowpass.data(), static_cast<int>(lowpass.size()), s.padded, s.lowpass);
    multiplyInPlace(s.source, s.lowpass, bins);
    // Linear: the ears' spectra are summed over sources, and each pose
    // needs one inverse transform per ear whatever the number of sources.
    for (int p = 0; p < poses; ++p) {
      hrirs_.responsesAt(s.views[p][i].azimuth_deg, s.hrir_left.data(), s.hrir_right.data());
      fft.forward(s.hrir_left.data(), hrir_length, s.padded, s.filter);
      multiplyAccumulate(s.source, s.filter, bins, s.sums[p][0]);
      fft.forward(s.hrir_right.data(), hrir_length, s.padded, s.filter);
      multiplyAccumulate(s.source, s.filter, bins, s.sums[p][1]);
    }
  }

  for (int p = 0; p < poses; ++p)
    for (int ear = 0; ear < 2; ++ear) fft.inverse(s.sums[p][ear], s.outputs[p][ear]);
  // Overlap-save: the first `history` outputs wrapped round; the rest are
  // the chunk.
  float* ears[2] = {out.left.data() + chunk_start, out.right.data() + chunk_start};
  if (!turning) {
    for (int ear = 0; ear < 2; ++ear) {
      const float* from_previous = s.outputs[0][ear].data() + history;
      std::copy(from_previous, from_previous + chunk, ears[ear]);
    }
    return;
  }
  detail::blendPoses(s.outputs, history, chunk, first + chunk_start, first, total, ears, false);
}

}  // namespace beft::hearing
