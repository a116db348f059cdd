#include "lib/transport/transport.hpp"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

#include "lib/transport/detail/repairing_source.hpp"
#include "lib/transport/detail/udpm_filter.hpp"
#include "lib/transport/detail/udpm_receiver.hpp"
#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/reject_counter.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::transport {

namespace {

class DirectSource : public Receiver {
 public:
  DirectSource(const udpm::Endpoint& endpoint, const Selection& spec, std::size_t batch)
      : receiver_(endpoint, spec, batch), what_(udpm_filter::describe(spec)) {}

  int fd() const override { return receiver_.fd(); }
  int drain(const Handler& handler) override { return receiver_.drain(handler); }
  std::string description() const override {
    return "own receive socket (" + std::to_string(receiver_.receiveBufferBytes() / 1024) + " KiB buffer), " +
           (receiver_.countsLosses() ? std::string("every channel, losses counted") : "kernel filter: " + what_);
  }
  uint64_t kernelDropped() const override { return receiver_.stats().kernel_dropped; }
  int receiveBufferBytes() const override { return receiver_.receiveBufferBytes(); }

 private:
  udpm::Receiver receiver_;
  std::string what_;
};

// LCM's own receive path: subscriptions to the spec's channels (or to every
// channel when it lists what to drop), checked against the spec here.
class LcmSource : public Receiver {
 public:
  LcmSource(lcm::LCM& lcm, const std::string& url, Selection spec, int queue_capacity)
      : lcm_(lcm), spec_(std::move(spec)) {
    std::set<std::string> channels;
    bool everything = spec_.mode == Selection::Mode::RejectListed;
    for (const auto& rule : spec_.rules) {
      if (!isPlainChannel(rule.channel)) everything = true;
      channels.insert(rule.channel);
    }
    if (everything) channels = {".*"};
    for (const auto& channel : channels) {
      // subscribeFunction: the member-pointer form crashes under GCC's -fsanitize=vptr.
      auto* subscription = lcm_.subscribeFunction(channel, &LcmSource::onMessageOf, this);
      subscription->setQueueCapacity(queue_capacity);  // LCM 1.3.1 keeps 30 by default
      subscriptions_.push_back(subscription);
    }
    if (udpm_filter::installAndReport(lcm_, url, spec_))
      what_ = "LCM's receive thread, kernel filter: " + udpm_filter::describe(spec_);
    else
      what_ = "LCM's receive thread, every channel";
  }
  ~LcmSource() override {
    for (auto* subscription : subscriptions_) lcm_.unsubscribe(subscription);
  }

  int fd() const override { return lcm_.getFileno(); }

  int drain(const Handler& handler) override {
    handler_ = &handler;
    handed_ = 0;
    int status = 0;
    while ((status = lcm_.handleTimeout(0)) > 0) {
    }
    handler_ = nullptr;
    return status < 0 ? -1 : handed_;
  }

  std::string description() const override { return what_; }

  static void onMessageOf(const lcm::ReceiveBuffer* buffer, const std::string& channel, LcmSource* self) {
    if (!self->handler_ || !udpm_filter::accepts(self->spec_, channel, buffer->data, buffer->data_size)) return;
    Message message;
    message.channel = channel;
    message.data = static_cast<const uint8_t*>(buffer->data);
    message.size = buffer->data_size;
    message.recv_utime = buffer->recv_utime;
    ++self->handed_;
    (*self->handler_)(message);
  }

 private:
  lcm::LCM& lcm_;
  Selection spec_;
  std::vector<lcm::Subscription*> subscriptions_;
  const Handler* handler_ = nullptr;
  int handed_ = 0;
  std::string what_;
};

// Hands on this run's messages under their plain names; another run's are
// dropped and counted (a receiver of every channel hears them).
class RunFilter : public Receiver {
 public:
  explicit RunFilter(std::unique_ptr<Receiver> inner) : inner_(std::move(inner)), own_(wire::runId()) {}
  int fd() const override { return inner_->fd(); }
  int drain(const Handler& handler) override {
    return inner_->drain([&](const Message& message) {
      const wire::RunChannel split = wire::splitRunChannel(message.channel);
      if (split.run_id != own_ && !wire::isUrlWideChannel(message.channel)) {
        wire::processRejects().count(std::string(split.base), {wire::Fault::kOtherRun, "", split.run_id});
        return;
      }
      Message plain = message;
      plain.channel = split.base;
      handler(plain);
    });
  }
  std::string description() const override {
    // The channels under their plain names, and the run once.
    std::string text = inner_->description();
    if (own_ == 0) return text;
    const std::string suffix = wire::runChannel("", own_);
    for (auto at = text.find(suffix); at != std::string::npos; at = text.find(suffix, at)) text.erase(at, suffix.size());
    return text + ", " + wire::describeRun(own_);
  }
  int receiveBufferBytes() const override { return inner_->receiveBufferBytes(); }
  uint64_t kernelDropped() const override { return inner_->kernelDropped(); }
  RepairStats repairStats() const override { return inner_->repairStats(); }
  bool holds(uint64_t sender, const std::string& channel, uint64_t sequence, bool owed_unheard) override {
    return inner_->holds(sender, wire::runChannel(channel, own_), sequence, owed_unheard);
  }

 private:
  std::unique_ptr<Receiver> inner_;
  int64_t own_;
};

// The selection as it reads on the wire: this run's channel names.
Selection onThisRun(const Selection& selection) {
  Selection named = selection;
  for (auto& rule : named.rules) rule.channel = wire::runChannel(rule.channel);
  return named;
}

// A receiver that takes whole channels also takes the senders' states,
// which tell it of a lost last message (a recorder's "everything" has them).
Selection withSenderStates(const Selection& selection) {
  if (selection.mode != Selection::Mode::AcceptListed) return selection;
  const bool takes_whole_channels =
      std::any_of(selection.rules.begin(), selection.rules.end(), [](const Rule& rule) { return rule.field.empty(); });
  if (!takes_whole_channels) return selection;
  Selection with_states = selection;
  with_states.rules.push_back(channelRule(channels::kSenderState.name));
  return with_states;
}

}  // namespace

int Receiver::receive(int timeout_ms, const Handler& handler) {
  if (!udpm::waitReadable({fd()}, timeout_ms)) return 0;
  return drain(handler);
}

bool directReceiveFor(const std::string& url, std::string* why) {
  if (const char* setting = std::getenv("BEFT_UDPM_RECEIVER"); setting && std::string(setting) == "0") {
    if (why) *why = "turned off by BEFT_UDPM_RECEIVER=0";
    return false;
  }
  return udpm::parseUrl(url, why).has_value();
}

SplitReceivers openSplitReceivers(lcm::LCM& lcm, const std::string& url, const Selection& wake,
                                  const Selection& queued, std::size_t queued_batch, int lcm_queue_capacity) {
  using Mode = Selection::Mode;
  if (wake.mode != Mode::AcceptListed) throw std::invalid_argument("openSplitReceivers: wake must list its channels");
  std::set<std::string> wake_channels;
  for (const auto& rule : wake.rules) wake_channels.insert(rule.channel);
  const bool queues_nothing = queued.mode == Mode::AcceptListed && queued.rules.empty();
  SplitReceivers sources;
  if (directReceiveFor(url)) {
    Selection only_queued = queued;
    if (queued.mode == Mode::RejectListed)
      for (const auto& channel : wake_channels) only_queued.rules.push_back(channelRule(channel));
    if (!queues_nothing) sources.queued = openReceiver(lcm, url, only_queued, queued_batch);
    sources.wake = openReceiver(lcm, url, wake, 4);
    return sources;
  }
  // One spec that takes both.
  Selection both = queued;
  if (queued.mode == Mode::AcceptListed) {
    both.rules.insert(both.rules.end(), wake.rules.begin(), wake.rules.end());
  } else {
    both.rules.clear();
    for (const auto& rule : queued.rules)
      if (!wake_channels.count(rule.channel)) both.rules.push_back(rule);
  }
  sources.wake = openReceiver(lcm, url, both, queued_batch, lcm_queue_capacity);
  return sources;
}

bool roomToGather(int receive_buffer_bytes) {
  constexpr int kGatherBufferBytes = 2 << 20;
  if (receive_buffer_bytes < 0 || receive_buffer_bytes >= kGatherBufferBytes) return true;
  log::warn("the kernel granted a ", receive_buffer_bytes / 1024,
            " KiB receive buffer (recv_buf_size in the LCM URL, capped by net.core.rmem_max): reading each "
            "message as it comes");
  return false;
}

std::unique_ptr<Receiver> openReceiver(lcm::LCM& lcm, const std::string& url, const Selection& spec,
                                       std::size_t batch, int lcm_queue_capacity) {
  const Selection with_states = withSenderStates(spec);
  const Selection named = spec.every_run ? with_states : onThisRun(with_states);
  std::unique_ptr<Receiver> receiver;
  if (directReceiveFor(url)) receiver = std::make_unique<DirectSource>(*udpm::parseUrl(url), named, batch);
  else receiver = std::make_unique<LcmSource>(lcm, url, named, lcm_queue_capacity);
  receiver = detail::withRepair(std::move(receiver), lcm, named);
  if (spec.every_run) return receiver;
  return std::make_unique<RunFilter>(std::move(receiver));
}

int drainSplit(Receiver& wake, Receiver* queued, const Handler& handler) {
  int total = 0;
  for (Receiver* source : {queued, &wake, queued}) {
    if (source == nullptr) continue;
    const int count = source->drain(handler);
    if (count < 0) return -1;
    total += count;
  }
  return total;
}

bool waitReadable(std::initializer_list<int> fds, int timeout_ms) { return udpm::waitReadable(fds, timeout_ms); }

}  // namespace beft::transport
