// Which camera frames a recording keeps (beft-record --camera, beft-run
// --record-camera): all of them, those of every N-th tick, or none. The
// frames dominate a run's log; the live processes get every frame whatever
// is kept.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace beft::record {

class CameraSampling {
 public:
  // "all" (the default), "none" or "every:N" with N >= 1 (every:1 is all).
  // std::invalid_argument for anything else.
  static CameraSampling parse(const std::string& text);
  // What parse would refuse in text, or "" (a command-line check).
  static std::string problemWith(const std::string& text);
  std::string text() const;  // as parse takes it

  // Whether a message heard on channel (of any run) is recorded. Every
  // message off the CAMERA_* channels is. On them, a camera frame is kept
  // when its tick is a multiple of N; a message that is no camera frame (its
  // tick unreadable) is kept too, unless none is kept: the log holds what
  // it cannot judge, and its readers refuse it.
  bool keeps(std::string_view channel, const uint8_t* data, std::size_t size) const;

  bool keepsAll() const { return every_ == 1; }

 private:
  int64_t every_ = 1;  // 0: none
};

// Whether a channel (as heard, with or without a run id) carries camera frames.
bool isCameraChannel(std::string_view channel);

}  // namespace beft::record
