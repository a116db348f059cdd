#include "lib/hearing/fft_convolver.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace beft::hearing {

// ---- AlignedBuffer ----

template <typename T>
AlignedBuffer<T>::AlignedBuffer(AlignedBuffer&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)),
      capacity_(std::exchange(other.capacity_, 0)) {}

template <typename T>
AlignedBuffer<T>& AlignedBuffer<T>::operator=(AlignedBuffer&& other) noexcept {
  if (this != &other) {
    fftwf_free(data_);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
    capacity_ = std::exchange(other.capacity_, 0);
  }
  return *this;
}

template <typename T>
AlignedBuffer<T>::~AlignedBuffer() {
  fftwf_free(data_);
}

template <typename T>
void AlignedBuffer<T>::resize(std::size_t size) {
  if (size > capacity_) {
    void* memory = fftwf_malloc(size * sizeof(T));
    if (memory == nullptr) throw std::bad_alloc();
    fftwf_free(data_);
    data_ = static_cast<T*>(memory);
    capacity_ = size;
  }
  size_ = size;
}

template class AlignedBuffer<float>;
template class AlignedBuffer<std::complex<float>>;

// ---- sizes ----

int fastFftSize(int minimum) {
  if (minimum <= 1) return 1;
  for (int n = minimum;; ++n) {
    int rest = n;
    for (int factor : {2, 3, 5})
      while (rest % factor == 0) rest /= factor;
    if (rest == 1) return n;
  }
}

// ---- plans ----

namespace {

struct PlanPair {
  fftwf_plan forward;
  fftwf_plan inverse;
};

// Plans live until the process ends (a RealFft of a size seen once is likely
// to be made again, one per block length) and are destroyed then, so leak
// checkers see nothing left behind.
class PlanCache {
 public:
  ~PlanCache() {
    for (auto& [size, pair] : plans_) {
      fftwf_destroy_plan(pair.forward);
      fftwf_destroy_plan(pair.inverse);
    }
  }

  PlanPair plansFor(int size) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto found = plans_.find(size);
    if (found != plans_.end()) return found->second;
    Samples time(size);
    Spectrum frequency(size / 2 + 1);
    auto* complex_data = reinterpret_cast<fftwf_complex*>(frequency.data());
    PlanPair pair;
    pair.forward = fftwf_plan_dft_r2c_1d(size, time.data(), complex_data, FFTW_ESTIMATE);
    pair.inverse = fftwf_plan_dft_c2r_1d(size, complex_data, time.data(), FFTW_ESTIMATE);
    if (pair.forward == nullptr || pair.inverse == nullptr) {
      throw std::runtime_error("FFTW could not plan a real FFT of size " + std::to_string(size));
    }
    plans_.emplace(size, pair);
    return pair;
  }

 private:
  std::mutex mutex_;
  std::map<int, PlanPair> plans_;
};

PlanPair plansFor(int size) {
  static PlanCache cache;
  return cache.plansFor(size);
}

}  // namespace

RealFft::RealFft(int size) : size_(size) {
  if (size < 1) throw std::invalid_argument("FFT size must be >= 1, got " + std::to_string(size));
  const PlanPair pair = plansFor(size);
  forward_plan_ = pair.forward;
  inverse_plan_ = pair.inverse;
}

void RealFft::forward(const float* x, int n, Samples& scratch, Spectrum& spectrum) const {
  if (n < 0 || n > size_) {
    throw std::invalid_argument("RealFft::forward: " + std::to_string(n) + " samples do not fit a transform of " +
                                std::to_string(size_));
  }
  scratch.resize(size_);
  spectrum.resize(bins());
  if (n > 0) std::memcpy(scratch.data(), x, sizeof(float) * n);
  std::fill(scratch.data() + n, scratch.data() + size_, 0.0f);
  fftwf_execute_dft_r2c(static_cast<fftwf_plan>(forward_plan_), scratch.data(),
                        reinterpret_cast<fftwf_complex*>(spectrum.data()));
}

void RealFft::forward(const std::vector<float>& input, std::vector<std::complex<float>>& output) const {
  thread_local Samples scratch;
  thread_local Spectrum spectrum;
  forward(input.data(), std::min(static_cast<int>(input.size()), size_), scratch, spectrum);
  output.assign(spectrum.data(), spectrum.data() + bins());
}

void RealFft::inverse(Spectrum& spectrum, Samples& out) const {
  if (static_cast<int>(spectrum.size()) < bins()) {
    throw std::invalid_argument("RealFft::inverse: spectrum of " + std::to_string(spectrum.size()) +
                                " bins, need " + std::to_string(bins()));
  }
  out.resize(size_);
  fftwf_execute_dft_c2r(static_cast<fftwf_plan>(inverse_plan_), reinterpret_cast<fftwf_complex*>(spectrum.data()),
                        out.data());
  const float scale = 1.0f / static_cast<float>(size_);
  for (int i = 0; i < size_; ++i) out[i] *= scale;
}

// ---- spectral products ----

void multiplyAccumulate(const Spectrum& a, const Spectrum& b, int bins, Spectrum& acc) {
  // Written out on floats: std::complex's operator* checks for NaN/inf
  // (C99 Annex G), which would keep the compiler from vectorising the loop.
  const float* pa = reinterpret_cast<const float*>(a.data());
  const float* pb = reinterpret_cast<const float*>(b.data());
  float* out = reinterpret_cast<float*>(acc.data());
  for (int k = 0; k < bins; ++k) {
    const float ar = pa[2 * k], ai = pa[2 * k + 1], br = pb[2 * k], bi = pb[2 * k + 1];
    out[2 * k] += ar * br - ai * bi;
    out[2 * k + 1] += ar * bi + ai * br;
  }
}

void multiplyInPlace(Spectrum& a, const Spectrum& b, int bins) {
  float* pa = reinterpret_cast<float*>(a.data());
  const float* pb = reinterpret_cast<const float*>(b.data());
  for (int k = 0; k < bins; ++k) {
    const float ar = pa[2 * k], ai = pa[2 * k + 1], br = pb[2 * k], bi = pb[2 * k + 1];
    pa[2 * k] = ar * br - ai * bi;
    pa[2 * k + 1] = ar * bi + ai * br;
  }
}

std::vector<float> convolve(const std::vector<float>& x, const std::vector<float>& h) {
  if (x.empty() || h.empty()) return {};
  const int length = static_cast<int>(x.size() + h.size() - 1);
  const RealFft fft(fastFftSize(length));
  Samples scratch, out;
  Spectrum spectrum_x, spectrum_h, product;
  fft.forward(x.data(), static_cast<int>(x.size()), scratch, spectrum_x);
  fft.forward(h.data(), static_cast<int>(h.size()), scratch, spectrum_h);
  product.resize(fft.bins());
  std::fill(product.data(), product.data() + fft.bins(), std::complex<float>(0, 0));
  multiplyAccumulate(spectrum_x, spectrum_h, fft.bins(), product);
  fft.inverse(product, out);
  return std::vector<float>(out.data(), out.data() + length);
}

}  // namespace beft::hearing
