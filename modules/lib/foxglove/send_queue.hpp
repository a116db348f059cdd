// What waits to be sent to one client, bounded by bytes, so that a slow
// viewer costs the bridge a fixed amount of memory and never slows the run:
// data frames are dropped (oldest first, and counted) to make room; control
// text (serverInfo, advertise, status, ...) is never dropped. A frame with a
// latest_wins_key replaces the queued frame of the same key (a bulky
// channel - camera, map, scene - needs only its newest message), keeping
// that frame's place in the queue.
//
// Not thread-safe: one thread (the client's I/O thread) owns a queue.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>

namespace beft::foxglove {

struct Frame {
  std::string bytes;
  bool binary = false;  // a binary data frame (droppable); text frames are control messages (kept)
  std::optional<uint32_t> latest_wins_key;  // e.g. the channel id of a bulky channel

  bool droppable() const { return binary; }
};

class SendQueue {
 public:
  explicit SendQueue(std::size_t max_bytes = std::size_t{8} << 20);

  // Queues frame. A keyed frame replaces the queued frame of its key (that
  // one is counted as replaced). Then, while the queue holds more than
  // max_bytes, the oldest droppable frame is dropped and counted, the new
  // one too if nothing older is left; control text alone may exceed the
  // bound.
  void push(Frame frame);

  bool empty() const { return frames_.empty(); }
  std::size_t size() const { return frames_.size(); }
  std::size_t bytes() const { return bytes_; }  // of every queued frame
  std::size_t maxBytes() const { return max_bytes_; }

  // The oldest frame; the queue must not be empty (std::logic_error). A
  // frame handed to an asynchronous write must be popped, not read here: a
  // later push may replace or drop any queued frame.
  const Frame& front() const;
  // Takes the oldest frame out; the queue must not be empty (std::logic_error).
  Frame pop();

  // Frames dropped for room since the last call (then 0 again).
  uint64_t takeDropped();
  // Frames replaced by a newer frame of their key since the last call.
  uint64_t takeReplaced();

 private:
  bool replaceKeyed(Frame& frame);
  void dropForRoom();

  std::size_t max_bytes_;
  std::size_t bytes_ = 0;
  std::deque<Frame> frames_;
  uint64_t dropped_ = 0;
  uint64_t replaced_ = 0;
};

}  // namespace beft::foxglove
