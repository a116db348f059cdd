// A real-to-complex FFT of one size through FFTW (single precision). The plan
// is made once; transforming is const and safe from several threads, each
// with its own buffers (FFTW's new-array execute, planned for unaligned data).
#pragma once

#include <complex>
#include <vector>

namespace beft::hearing {

class RealFft {
 public:
  explicit RealFft(int size);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;
  RealFft(RealFft&& other) noexcept;
  RealFft& operator=(RealFft&& other) noexcept;

  int size() const { return size_; }
  int bins() const { return size_ / 2 + 1; }  // 0 .. Nyquist
  // `input` holds size() samples (shorter input is zero-padded); `output` gets bins() values.
  void forward(const std::vector<float>& input, std::vector<std::complex<float>>& output) const;

 private:
  int size_ = 0;
  void* plan_ = nullptr;  // fftwf_plan
};

}  // namespace beft::hearing
