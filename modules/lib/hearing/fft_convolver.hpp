// FFT convolution with FFTW3 (single precision): real transforms of one size
// whose plans are made once per size and shared by every thread, buffers
// aligned as FFTW's plans expect, and the spectral products a block
// convolution (overlap-save) is made of.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace beft::hearing {

// A buffer allocated with fftwf_malloc: FFTW's SIMD plans are only valid for
// arrays aligned like the ones they were planned with, so every array a plan
// runs on comes from here.
template <typename T>
class AlignedBuffer {
 public:
  AlignedBuffer() = default;
  explicit AlignedBuffer(std::size_t size) { resize(size); }
  AlignedBuffer(const AlignedBuffer&) = delete;
  AlignedBuffer& operator=(const AlignedBuffer&) = delete;
  AlignedBuffer(AlignedBuffer&& other) noexcept;
  AlignedBuffer& operator=(AlignedBuffer&& other) noexcept;
  ~AlignedBuffer();

  // Grows (contents lost) or shrinks; never frees on shrinking.
  void resize(std::size_t size);
  std::size_t size() const { return size_; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

using Samples = AlignedBuffer<float>;
using Spectrum = AlignedBuffer<std::complex<float>>;

// The smallest size >= minimum whose only prime factors are 2, 3 and 5
// (FFTW is fastest on those).
int fastFftSize(int minimum);

// Forward and inverse real FFT of one size. The plans come from a process-wide
// cache (FFTW's planner is not thread-safe: plans are made under a mutex, once
// per size, with FFTW_ESTIMATE so that the plan, and with it every rounding,
// is the same in every process); executing them is thread-safe.
class RealFft {
 public:
  explicit RealFft(int size);
  int size() const { return size_; }
  int bins() const { return size_ / 2 + 1; }

  // Transforms x[0..n) zero-padded to size() into spectrum (resized to bins()).
  // n <= size(). Uses `scratch` (resized to size()) for the padded input.
  void forward(const float* x, int n, Samples& scratch, Spectrum& spectrum) const;
  // The same for analysis: the first size() samples of `input` (zero-padded
  // if shorter) into `output` (resized to bins()), through aligned scratch
  // buffers of the calling thread.
  void forward(const std::vector<float>& input, std::vector<std::complex<float>>& output) const;
  // Inverse of forward, scaled by 1/size() (so inverse(forward(x)) == x);
  // `spectrum` is overwritten, `out` resized to size().
  void inverse(Spectrum& spectrum, Samples& out) const;

 private:
  int size_;
  void* forward_plan_;  // fftwf_plan, owned by the cache
  void* inverse_plan_;
};

// acc[k] += a[k] * b[k] over the first `bins` bins.
void multiplyAccumulate(const Spectrum& a, const Spectrum& b, int bins, Spectrum& acc);
// a[k] *= b[k] over the first `bins` bins.
void multiplyInPlace(Spectrum& a, const Spectrum& b, int bins);

// Full linear convolution of x and h (x.size() + h.size() - 1 samples) through
// one FFT of a fast size; empty if either is empty.
std::vector<float> convolve(const std::vector<float>& x, const std::vector<float>& h);

}  // namespace beft::hearing
