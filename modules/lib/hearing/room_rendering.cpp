// The room's part of a block (binaural_renderer.hpp): early reflections by
// image sources and the diffuse tail, added to the direct sound.
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "lib/hearing/binaural_renderer.hpp"
#include "lib/hearing/fft_convolver.hpp"
#include "lib/hearing/room_model.hpp"
#include "lib/hearing/source_reading.hpp"

namespace beft::hearing {

namespace {

using detail::progressAt;
using detail::readMoving;
using detail::readStill;
using detail::SourceView;
using detail::kMaxChunk;

// Taps before an image's arrival in its response: the cubic fractional
// delay reaches two samples back.
constexpr int kLead = 2;

struct RoomScratch {
  Samples segment, padded, input;
  Spectrum source, filter, product;
  Spectrum sums[2][2];    // [pose][ear]
  Samples outputs[2][2];  // [pose][ear]
  std::vector<float> hrir_left, hrir_right;
  std::vector<std::vector<ImageSource>> images;  // [pose * sources + source]
  std::vector<double> references;                // delay the segment is read at [samples]
  std::vector<std::vector<float>> responses;     // [(pose * sources + source) * 2 + ear]
};

RoomScratch& roomScratch() {
  thread_local RoomScratch scratch;
  return scratch;
}

double directDelaySamples(const RenderedSource& source, const HeadPose& pose, double sample_rate) {
  const double distance = std::max(BinauralRenderer::kMinDistance, (source.position - pose.centre).norm());
  return distance / BinauralRenderer::kSpeedOfSound * sample_rate;
}

// h[n] += gain * hrir[n - offset] with a fractional offset (>= kLead - 1):
// Catmull-Rom weights over the four nearest whole offsets (the
// interpolation looped_signal reads with).
void placeResponse(const float* hrir, int hrir_length, double offset, float gain, std::vector<float>& h) {
  const double whole = std::floor(offset);
  const float t = static_cast<float>(1.0 - (offset - whole));
  const float t2 = t * t, t3 = t2 * t;
  const float weights[4] = {-0.5f * t3 + t2 - 0.5f * t, 1.5f * t3 - 2.5f * t2 + 1.0f,
                            -1.5f * t3 + 2.0f * t2 + 0.5f * t, 0.5f * t3 - 0.5f * t2};
  // weights[j] belongs to the lag whole + 2 - j.
  const int base = static_cast<int>(whole);
  for (int j = 0; j < 4; ++j) {
    const float w = gain * weights[j];
    if (w == 0) continue;
    float* out = h.data() + base + 2 - j;
    for (int k = 0; k < hrir_length; ++k) out[k] += w * hrir[k];
  }
}

// out[j] += the poses' outputs blended by a raised cosine, as the direct sound is.
void addBlended(const Samples (&outputs)[2][2], int history, int chunk, int64_t chunk_first, int64_t first,
                int total, bool turning, float* const ears[2]) {
  if (!turning) {
    for (int ear = 0; ear < 2; ++ear)
      for (int j = 0; j < chunk; ++j) ears[ear][j] += outputs[0][ear][history + j];
    return;
  }
  detail::blendPoses(outputs, history, chunk, chunk_first, first, total, ears, true);
}

// The source read over a segment at a delay (moving from the previous
// pose's to the current one's when turning), times gain.
void readSource(const RenderedSource& source, const BlockRequest& request, bool turning, double gain,
                const double delays[2], double advance, int64_t segment_first, int segment_length, float* out) {
  const SourceView before{0, gain, delays[0]}, after{0, gain, turning ? delays[1] : delays[0]};
  if (!turning) {
    readStill(source.signal->samples, before, advance, segment_first, segment_length, out);
    return;
  }
  // More than a block before the block, readMoving holds the motion at its
  // value one block back (u = -1): read that stretch in one still run.
  const int64_t first = request.first_sample;
  const int total = request.num_samples;
  const int held = static_cast<int>(std::clamp<int64_t>(first - total - segment_first, 0, segment_length));
  if (held > 0) {
    const double u = -1.0;
    const SourceView back{0, std::max(0.0, before.gain + u * (after.gain - before.gain)),
                          before.delay_samples + u * (after.delay_samples - before.delay_samples)};
    readStill(source.signal->samples, back, advance, segment_first, held, out);
  }
  readMoving(source.signal->samples, before, after, advance, segment_first + held, segment_length - held, first, total,
             out + held);
}

}  // namespace

void BinauralRenderer::addRoom(const BlockRequest& request, bool turning, StereoBlock& out) const {
  if (request.sources.empty()) return;
  addEarlyReflections(request, turning, out);
  addTail(request, turning, out);
}

// Each source's image sources for each pose as a pair of responses (every
// image's HRIRs at its delay behind the source's direct delay), then one
// overlap-save convolution per source, pose and ear.
void BinauralRenderer::addEarlyReflections(const BlockRequest& request, bool turning, StereoBlock& out) const {
  const RoomModel& room = *request.room;
  if (room.settings().reflection_order == 0) return;
  RoomScratch& s = roomScratch();
  const int poses = turning ? 2 : 1;
  const HeadPose* pose_of[2] = {&request.previous, &request.current};
  const std::size_t count = request.sources.size();
  const int hrir_length = hrirs_.length();
  s.images.resize(poses * count);
  s.references.resize(poses * count);
  int response_length = 0;
  for (int p = 0; p < poses; ++p)
    for (std::size_t i = 0; i < count; ++i) {
      const RenderedSource& source = request.sources[i];
      const std::size_t at = p * count + i;
      s.images[at] = room.imageSources(source.position, source.room_owner, pose_of[p]->centre);
      s.references[at] = directDelaySamples(source, *pose_of[p], sample_rate_) - kLead;
      for (const ImageSource& image : s.images[at]) {
        const double offset = image.path_m / kSpeedOfSound * sample_rate_ - s.references[at];
        response_length = std::max(response_length, static_cast<int>(std::floor(offset)) + kLead + 2 + hrir_length);
      }
    }
  if (response_length == 0) return;

  s.responses.resize(poses * count * 2);
  s.hrir_left.resize(hrir_length);
  s.hrir_right.resize(hrir_length);
  for (int p = 0; p < poses; ++p)
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t at = p * count + i;
      std::vector<float>& left = s.responses[2 * at];
      std::vector<float>& right = s.responses[2 * at + 1];
      left.assign(response_length, 0.0f);
      right.assign(response_length, 0.0f);
      for (const ImageSource& image : s.images[at]) {
        const double offset = std::max<double>(kLead - 1, image.path_m / kSpeedOfSound * sample_rate_ - s.references[at]);
        const float gain = static_cast<float>(image.amplitude / std::max(kMinDistance, image.path_m));
        hrirs_.responsesAt(headAzimuthDeg(*pose_of[p], image.position), s.hrir_left.data(), s.hrir_right.data());
        placeResponse(s.hrir_left.data(), hrir_length, offset, gain, left);
        placeResponse(s.hrir_right.data(), hrir_length, offset, gain, right);
      }
    }

  const int total = request.num_samples;
  const int history = response_length - 1;
  for (int chunk_start = 0; chunk_start < total; chunk_start += kMaxChunk) {
    const int chunk = std::min(kMaxChunk, total - chunk_start);
    const int segment_length = chunk + history;
    const int64_t segment_first = request.first_sample + chunk_start - history;
    const RealFft fft(fastFftSize(segment_length));
    const int bins = fft.bins();
    for (int p = 0; p < poses; ++p)
      for (Spectrum& sum : s.sums[p]) {
        sum.resize(bins);
        std::fill(sum.data(), sum.data() + bins, std::complex<float>(0, 0));
      }
    s.segment.resize(segment_length);
    for (std::size_t i = 0; i < count; ++i) {
      if (s.images[i].empty() && (!turning || s.images[count + i].empty())) continue;
      const double delays[2] = {s.references[i], turning ? s.references[count + i] : s.references[i]};
      readSource(request.sources[i], request, turning, request.sources[i].level, delays, hrirs_.centreDelaySamples(),
                 segment_first, segment_length, s.segment.data());
      fft.forward(s.segment.data(), segment_length, s.padded, s.source);
      for (int p = 0; p < poses; ++p)
        for (int ear = 0; ear < 2; ++ear) {
          const std::vector<float>& h = s.responses[2 * (p * count + i) + ear];
          fft.forward(h.data(), response_length, s.padded, s.filter);
          multiplyAccumulate(s.source, s.filter, bins, s.sums[p][ear]);
        }
    }
    for (int p = 0; p < poses; ++p)
      for (int ear = 0; ear < 2; ++ear) fft.inverse(s.sums[p][ear], s.outputs[p][ear]);
    float* ears[2] = {out.left.data() + chunk_start, out.right.data() + chunk_start};
    addBlended(s.outputs, history, chunk, request.first_sample + chunk_start, request.first_sample, total, turning,
               ears);
  }
}

// The sum of the sources, each at its direct delay plus the tail's onset
// (moving with the head like the direct sound), through the tail's two
// responses: diffuse, so the same for every direction and head pose.
void BinauralRenderer::addTail(const BlockRequest& request, bool turning, StereoBlock& out) const {
  const LateReverb* tail = request.room->tail();
  if (tail == nullptr) return;
  RoomScratch& s = roomScratch();
  const HeadPose* pose_of[2] = {&request.previous, &request.current};
  const double onset = tail->onset() * sample_rate_;
  const double amplitude = request.room->tailAmplitude();
  const int total = request.num_samples;
  const int history = tail->length() - 1;
  for (int chunk_start = 0; chunk_start < total; chunk_start += kMaxChunk) {
    const int chunk = std::min(kMaxChunk, total - chunk_start);
    const int segment_length = chunk + history;
    const int64_t segment_first = request.first_sample + chunk_start - history;
    const RealFft fft(fastFftSize(segment_length));
    s.input.resize(segment_length);
    std::fill(s.input.data(), s.input.data() + segment_length, 0.0f);
    s.segment.resize(segment_length);
    for (const RenderedSource& source : request.sources) {
      const double delays[2] = {directDelaySamples(source, *pose_of[0], sample_rate_) + onset,
                                directDelaySamples(source, *pose_of[1], sample_rate_) + onset};
      readSource(source, request, turning, source.level * amplitude, delays, 0.0, segment_first, segment_length,
                 s.segment.data());
      for (int j = 0; j < segment_length; ++j) s.input[j] += s.segment[j];
    }
    fft.forward(s.input.data(), segment_length, s.padded, s.source);
    const std::pair<Spectrum, Spectrum>& responses = tail->spectra(fft);
    const Spectrum* of_ear[2] = {&responses.first, &responses.second};
    float* ears[2] = {out.left.data() + chunk_start, out.right.data() + chunk_start};
    for (int ear = 0; ear < 2; ++ear) {
      s.product.resize(fft.bins());
      std::fill(s.product.data(), s.product.data() + fft.bins(), std::complex<float>(0, 0));
      multiplyAccumulate(s.source, *of_ear[ear], fft.bins(), s.product);
      fft.inverse(s.product, s.outputs[0][ear]);
      for (int j = 0; j < chunk; ++j) ears[ear][j] += s.outputs[0][ear][history + j];
    }
  }
}

}  // namespace beft::hearing
