#include "lib/foxglove/send_queue.hpp"

#include <stdexcept>

namespace beft::foxglove {

SendQueue::SendQueue(std::size_t max_bytes) : max_bytes_(max_bytes) {}

void SendQueue::push(Frame frame) {
  if (!replaceKeyed(frame)) {
    bytes_ += frame.bytes.size();
    frames_.push_back(std::move(frame));
  }
  dropForRoom();
}

bool SendQueue::replaceKeyed(Frame& frame) {
  if (!frame.latest_wins_key) return false;
  for (Frame& queued : frames_) {
    if (queued.latest_wins_key != frame.latest_wins_key) continue;
    bytes_ = bytes_ - queued.bytes.size() + frame.bytes.size();
    queued = std::move(frame);
    ++replaced_;
    return true;
  }
  return false;
}

void SendQueue::dropForRoom() {
  auto it = frames_.begin();
  while (bytes_ > max_bytes_ && it != frames_.end()) {
    if (!it->droppable()) {
      ++it;
      continue;
    }
    bytes_ -= it->bytes.size();
    it = frames_.erase(it);
    ++dropped_;
  }
}

const Frame& SendQueue::front() const {
  if (frames_.empty()) throw std::logic_error("SendQueue::front on an empty queue");
  return frames_.front();
}

Frame SendQueue::pop() {
  if (frames_.empty()) throw std::logic_error("SendQueue::pop on an empty queue");
  Frame frame = std::move(frames_.front());
  frames_.pop_front();
  bytes_ -= frame.bytes.size();
  return frame;
}

uint64_t SendQueue::takeDropped() {
  const uint64_t count = dropped_;
  dropped_ = 0;
  return count;
}

uint64_t SendQueue::takeReplaced() {
  const uint64_t count = replaced_;
  replaced_ = 0;
  return count;
}

}  // namespace beft::foxglove
