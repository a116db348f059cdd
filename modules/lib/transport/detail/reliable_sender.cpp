#include "lib/transport/detail/reliable_sender.hpp"

#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <beft/repair_request_t.hpp>
#include <beft/sender_state_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/clocks.hpp"
#include "lib/common/log.hpp"
#include "lib/transport/detail/udpm_receiver.hpp"
#include "lib/transport/message_key.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::transport::detail {

namespace {

// The 8 bytes of a sender id as repair_request_t encodes it (after utime).
std::string encodedSender(uint64_t sender) {
  std::string bytes(8, '\0');
  for (int i = 0; i < 8; ++i) bytes[static_cast<std::size_t>(i)] = static_cast<char>(sender >> (56 - 8 * i));
  return bytes;
}

// In a keyed run, only a request with a valid tag is served.
bool requestAuthentic(const Message& message) {
  const MessageKey* key = processKey();
  if (key == nullptr) return true;
  std::size_t payload_size = 0;
  wire::Envelope envelope;
  if (!wire::splitEnvelope(message.data, message.size, payload_size, envelope)) return false;
  return tagValid(*key, message.channel, envelope, message.data, payload_size);
}

}  // namespace

std::unique_ptr<ReliableSender> ReliableSender::startFor(const std::string& url, Hooks hooks) {
  if (!udpm::parseUrl(url)) return nullptr;
  return std::unique_ptr<ReliableSender>(new ReliableSender(url, std::move(hooks)));
}

ReliableSender::ReliableSender(std::string url, Hooks hooks) : url_(std::move(url)), hooks_(std::move(hooks)) {
  wake_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (wake_fd_ < 0) throw std::runtime_error("reliable sender: eventfd failed");
  thread_ = std::thread([this] { run(); });
}

ReliableSender::~ReliableSender() {
  stop_ = true;
  const uint64_t one = 1;
  if (write(wake_fd_, &one, sizeof one) < 0) {
    // The thread still sees stop_ within its longest wait.
  }
  if (thread_.joinable()) thread_.join();
  close(wake_fd_);
}

void ReliableSender::leave(int quiet_ms, int longest_ms) {
  if (!ever_published_) return;  // nothing anybody could ask for
  const int64_t start = steadyMicros();
  last_request_us_ = start;
  leaving_ = true;
  const uint64_t one = 1;
  if (write(wake_fd_, &one, sizeof one) < 0) {
    // The thread sees leaving_ within its longest wait.
  }
  for (;;) {
    const int64_t now = steadyMicros();
    if (now - last_request_us_.load() >= int64_t{quiet_ms} * 1000 || now - start >= int64_t{longest_ms} * 1000) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

void ReliableSender::published() {
  ever_published_.store(true, std::memory_order_relaxed);
  last_publish_us_.store(steadyMicros(), std::memory_order_relaxed);
  if (!dirty_.exchange(true)) {
    const uint64_t one = 1;
    if (write(wake_fd_, &one, sizeof one) < 0) {
      // Full counter: the thread is already due to wake.
    }
  }
}

ReliableSender::Stats ReliableSender::stats() const { return {requests_, resent_, not_kept_, states_}; }

// The thread's state: the repair socket of the run it is on, and the pace of states.
struct ReliableSender::Loop {
  ReliableSender& owner;
  int64_t run_id = -1;
  std::unique_ptr<udpm::Receiver> requests;
  int state_interval_ms = kQuietMs;
  int64_t next_state_us = 0;
  bool ever_published = false;

  void followRun() {
    if (requests && run_id == wire::runId()) return;
    run_id = wire::runId();
    Selection selection;
    Rule rule;
    rule.channel = wire::runChannel(channels::kRepairRequest.name, run_id);
    rule.field_offset = 8;
    rule.field = encodedSender(owner.hooks_.sender);
    rule.what = "repair requests to this sender";
    selection.rules.push_back(rule);
    requests = std::make_unique<udpm::Receiver>(*udpm::parseUrl(owner.url_), selection, 16);
  }

  void serve(const Message& message) {
    beft::repair_request_t request;
    if (!requestAuthentic(message) || !wire::decodeFrom(std::string(message.channel), message.data, message.size, request))
      return;
    if (static_cast<uint64_t>(request.sender) != owner.hooks_.sender) return;
    ++owner.requests_;
    owner.last_request_us_ = steadyMicros();
    bool all_kept = true;
    for (int64_t sequence : request.sequences) {
      if (sequence < 1) continue;
      if (owner.hooks_.resend(request.channel, static_cast<uint64_t>(sequence))) {
        ++owner.resent_;
      } else {
        ++owner.not_kept_;
        all_kept = false;
      }
    }
    // What is no longer kept the state says at once (first_kept), so the receiver stops asking.
    if (!all_kept) sendState();
  }

  void sendState() {
    beft::sender_state_t state;
    state.utime = wallMicros();
    state.sender = static_cast<int64_t>(owner.hooks_.sender);
    state.process = owner.hooks_.process;
    for (const auto& channel : owner.hooks_.state()) {
      state.channels.push_back(channel.channel);
      state.last_sequences.push_back(static_cast<int64_t>(channel.last_sequence));
      state.first_kept.push_back(static_cast<int64_t>(channel.first_kept));
      state.stream_started.push_back(channel.stream_start_us);
    }
    state.count = static_cast<int32_t>(state.channels.size());
    state.leaving = owner.leaving_.load();
    std::vector<uint8_t> encoded(static_cast<std::size_t>(state.getEncodedSize()));
    state.encode(encoded.data(), 0, static_cast<int>(encoded.size()));
    owner.hooks_.publish(wire::runChannel(channels::kSenderState.name, run_id), encoded);
    ++owner.states_;
  }

  // How long to wait before the next state is due [ms]; -1: no state is due.
  int waitMs(int64_t now) const {
    if (owner.leaving_) return static_cast<int>(std::max<int64_t>(0, (next_state_us - now + 999) / 1000));
    if (owner.dirty_) {
      const int64_t quiet_until = owner.last_publish_us_.load(std::memory_order_relaxed) + kQuietMs * 1000;
      return static_cast<int>(std::max<int64_t>(0, (quiet_until - now + 999) / 1000));
    }
    if (!ever_published) return -1;
    return static_cast<int>(std::max<int64_t>(0, (next_state_us - now + 999) / 1000));
  }

  void sendDueState(int64_t now) {
    if (owner.leaving_) {
      if (now < next_state_us) return;
      sendState();
      next_state_us = now + int64_t{kLeavingStateMs} * 1000;
      return;
    }
    if (owner.dirty_) {
      if (now - owner.last_publish_us_.load(std::memory_order_relaxed) < kQuietMs * 1000) return;
      owner.dirty_ = false;
      ever_published = true;
      state_interval_ms = kQuietMs;
    } else if (!ever_published || now < next_state_us) {
      return;
    }
    sendState();
    state_interval_ms = std::min(state_interval_ms * 2, kSlowestStateMs);
    next_state_us = now + int64_t{state_interval_ms} * 1000;
  }
};

void ReliableSender::run() {
  Loop loop{*this};
  bool told_leaving = false;
  while (!stop_) {
    try {
      loop.followRun();
    } catch (const std::exception& error) {
      log::warn("loss repair: cannot open the repair socket (", error.what(), "); retrying");
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      continue;
    }
    const int wait_ms = loop.waitMs(steadyMicros());
    pollfd polled[2] = {{loop.requests->fd(), POLLIN, 0}, {wake_fd_, POLLIN, 0}};
    poll(polled, 2, wait_ms < 0 ? kSlowestStateMs : wait_ms);
    uint64_t wakes = 0;
    if (read(wake_fd_, &wakes, sizeof wakes) < 0) {
      // Nothing to read: woken by a request or the time.
    }
    if (stop_) break;
    loop.requests->drain([&](const Message& message) { loop.serve(message); });
    if (leaving_ && !told_leaving) {
      loop.next_state_us = 0;  // at once: receivers ask for what they miss now
      told_leaving = true;
    }
    loop.sendDueState(steadyMicros());
  }
}

}  // namespace beft::transport::detail
