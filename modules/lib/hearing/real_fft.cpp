#include "real_fft.hpp"

#include <fftw3.h>

#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

namespace beft::hearing {

namespace {
// FFTW's planner is not thread-safe; executing a plan is.
std::mutex& plannerMutex() {
  static std::mutex mutex;
  return mutex;
}
}  // namespace

RealFft::RealFft(int size) : size_(size) {
  if (size < 2) throw std::invalid_argument("FFT size must be at least 2, not " + std::to_string(size));
  std::vector<float> in(static_cast<std::size_t>(size));
  std::vector<std::complex<float>> out(static_cast<std::size_t>(bins()));
  std::lock_guard<std::mutex> lock(plannerMutex());
  plan_ = fftwf_plan_dft_r2c_1d(size, in.data(), reinterpret_cast<fftwf_complex*>(out.data()),
                                FFTW_ESTIMATE | FFTW_UNALIGNED | FFTW_PRESERVE_INPUT);
  if (plan_ == nullptr) throw std::runtime_error("FFTW could not plan an FFT of size " + std::to_string(size));
}

RealFft::~RealFft() {
  if (plan_ != nullptr) {
    std::lock_guard<std::mutex> lock(plannerMutex());
    fftwf_destroy_plan(static_cast<fftwf_plan>(plan_));
  }
}

RealFft::RealFft(RealFft&& other) noexcept : size_(other.size_), plan_(std::exchange(other.plan_, nullptr)) {}

RealFft& RealFft::operator=(RealFft&& other) noexcept {
  std::swap(size_, other.size_);
  std::swap(plan_, other.plan_);
  return *this;
}

void RealFft::forward(const std::vector<float>& input, std::vector<std::complex<float>>& output) const {
  output.resize(static_cast<std::size_t>(bins()));
  if (static_cast<int>(input.size()) >= size_) {
    fftwf_execute_dft_r2c(static_cast<fftwf_plan>(plan_), const_cast<float*>(input.data()),
                          reinterpret_cast<fftwf_complex*>(output.data()));
    return;
  }
  std::vector<float> padded(input);
  padded.resize(static_cast<std::size_t>(size_), 0.0f);
  fftwf_execute_dft_r2c(static_cast<fftwf_plan>(plan_), padded.data(),
                        reinterpret_cast<fftwf_complex*>(output.data()));
}

}  // namespace beft::hearing
