#include "lib/transport/detail/repairing_source.hpp"

#include <sys/epoll.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <chrono>
#include <limits>
#include <functional>
#include <set>

#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/common/clocks.hpp"
#include "lib/transport/detail/stream_tracker.hpp"
#include "lib/transport/message_key.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/reject_counter.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::transport::detail {

namespace {

StreamTracker::Options listeningFromNow(const Selection& selection) {
  StreamTracker::Options options;
  options.listening_since_us = wallMicros();
  options.hand_on_at_once = selection.every_run;  // a recorder
  return options;
}

bool isTransportChannel(std::string_view base) {
  return base == channels::kRepairRequest.name || base == channels::kSenderState.name;
}

// Which channels a selection takes whole (a rule without a field): those
// are streams. A rule that picks messages by their bytes (own firings)
// sees only some numbers of its channel, so gaps there are not losses.
//
// Not streams: the transport's own channels, the URL-wide beacons and the
// heartbeats (periodic, and only their latest counts), and, on a receiver of
// every run (the recorder), any run but this process's.
StreamTracker::Tracks tracksOf(const Selection& selection) {
  std::set<std::string, std::less<>> whole, picked;  // looked up by string_view: no copy per message
  for (const auto& rule : selection.rules) (rule.field.empty() ? whole : picked).insert(rule.channel);
  const bool everything = selection.mode == Selection::Mode::RejectListed;
  const int64_t own_run = wire::runId();
  return [whole, picked, everything, own_run](std::string_view channel) {
    const wire::RunChannel split = wire::splitRunChannel(channel);
    if (isTransportChannel(split.base) || wire::isUrlWideChannel(channel) || split.base == channels::kHeartbeat.name)
      return false;
    if (everything) return split.run_id == own_run && whole.count(channel) == 0 && picked.count(channel) == 0;
    return whole.count(channel) > 0;
  };
}

class RepairingSource : public Receiver {
 public:
  RepairingSource(std::unique_ptr<Receiver> inner, lcm::LCM& lcm, const Selection& selection)
      : inner_(std::move(inner)), lcm_(lcm), tracker_(tracksOf(selection), listeningFromNow(selection)) {
    timer_fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    epoll_fd_ = epoll_create1(EPOLL_CLOEXEC);
    epoll_event event{};
    event.events = EPOLLIN;
    const bool joined = timer_fd_ >= 0 && epoll_fd_ >= 0 &&
                        epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, inner_->fd(), &event) == 0 &&
                        epoll_ctl(epoll_fd_, EPOLL_CTL_ADD, timer_fd_, &event) == 0;
    if (!joined) {
      // Without the timer, repair requests go out when messages come.
      if (epoll_fd_ >= 0) close(epoll_fd_);
      epoll_fd_ = -1;
    }
  }
  ~RepairingSource() override {
    if (epoll_fd_ >= 0) close(epoll_fd_);
    if (timer_fd_ >= 0) close(timer_fd_);
  }

  int fd() const override { return epoll_fd_ >= 0 ? epoll_fd_ : inner_->fd(); }

  int drain(const Handler& handler) override {
    uint64_t expirations = 0;
    if (timer_fd_ >= 0 && read(timer_fd_, &expirations, sizeof expirations) < 0) {
      // Not expired: woken by a message.
    }
    int handed = 0;
    const Handler counted = [&](const Message& message) {
      ++handed;
      handler(message);
    };
    const int status = inner_->drain([&](const Message& message) { take(message, counted); });
    askForWhatIsMissing(counted);
    return status < 0 ? -1 : handed;
  }

  std::string description() const override { return inner_->description() + ", losses repaired"; }
  int receiveBufferBytes() const override { return inner_->receiveBufferBytes(); }
  uint64_t kernelDropped() const override { return inner_->kernelDropped(); }
  bool holds(uint64_t sender, const std::string& channel, uint64_t sequence, bool owed_unheard) override {
    if (tracker_.holds(sender, channel, sequence, steadyMicros(), owed_unheard)) return true;
    armTimer(tracker_.nextDueUs());
    return false;
  }
  RepairStats repairStats() const override {
    const auto& stats = tracker_.stats();
    RepairStats repairs;
    repairs.gaps = stats.gaps;
    repairs.repaired = stats.repaired;
    repairs.lost = stats.lost;
    repairs.duplicates = stats.duplicates;
    repairs.joined_late = stats.joined_late;
    repairs.requests = stats.requests;
    repairs.unauthenticated = unauthenticated_;
    repairs.waiting = tracker_.heldMessages();
    repairs.outstanding = tracker_.missingMessages();
    repairs.lost_named = tracker_.lostNamed();
    return repairs;
  }

 private:
  void take(const Message& received, const Handler& handler) {
    Message message = received;
    wire::Envelope envelope;
    const bool enveloped = wire::splitEnvelope(received.data, received.size, message.size, envelope);
    if (const MessageKey* key = key_) {
      if (!enveloped || !tagValid(*key, received.channel, envelope, message.data, message.size)) {
        ++unauthenticated_;
        wire::processRejects().count(std::string(wire::splitRunChannel(received.channel).base),
                                     {wire::Fault::kUnauthenticated, ""});
        return;
      }
    }
    const std::string_view base = wire::splitRunChannel(message.channel).base;
    if (base == channels::kSenderState.name) {
      beft::sender_state_t state;
      if (wire::decodeFrom(std::string(base), message.data, message.size, state))
        tracker_.onState(state, steadyMicros(), handler);
      return;
    }
    if (isTransportChannel(base)) return;
    if (enveloped && tracker_.tracks(message.channel)) tracker_.accept(message, envelope, steadyMicros(), handler);
    else handler(message);
  }

  void askForWhatIsMissing(const Handler& handler) {
    for (auto& request : tracker_.due(steadyMicros(), handler)) {
      const int64_t run = wire::splitRunChannel(request.channel).run_id;
      request.utime = wallMicros();
      request.requester = requester_;
      publish(lcm_, wire::runChannel(channels::kRepairRequest.name, run), request);
    }
    armTimer(tracker_.nextDueUs());
  }

  void armTimer(int64_t due_us) {
    if (timer_fd_ < 0) return;
    itimerspec when{};
    if (due_us != std::numeric_limits<int64_t>::max()) {
      const int64_t at = std::max<int64_t>(due_us, steadyMicros() + 1);
      when.it_value.tv_sec = at / 1000000;
      when.it_value.tv_nsec = (at % 1000000) * 1000;
    }
    timerfd_settime(timer_fd_, TFD_TIMER_ABSTIME, &when, nullptr);
  }

  std::unique_ptr<Receiver> inner_;
  lcm::LCM& lcm_;
  StreamTracker tracker_;
  int timer_fd_ = -1, epoll_fd_ = -1;
  uint64_t unauthenticated_ = 0;
  const MessageKey* key_ = processKey();
  std::string requester_ = std::to_string(getpid());
};

}  // namespace

std::unique_ptr<Receiver> withRepair(std::unique_ptr<Receiver> inner, lcm::LCM& lcm, const Selection& selection) {
  return std::make_unique<RepairingSource>(std::move(inner), lcm, selection);
}

}  // namespace beft::transport::detail
