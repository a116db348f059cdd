#include "lib/transport/publisher.hpp"

#include <sys/random.h>

#include <chrono>
#include <map>
#include <mutex>

#include "lib/common/clocks.hpp"
#include "lib/transport/detail/reliable_sender.hpp"
#include "lib/transport/detail/repair_buffer.hpp"
#include "lib/common/channels.hpp"
#include "lib/transport/message_key.hpp"
#include "lib/wire/envelope.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::transport {

namespace {

uint64_t drawSenderId() {
  uint64_t id = 0;
  while (id == 0)
    if (getrandom(&id, sizeof id, 0) != static_cast<ssize_t>(sizeof id)) id = 0;
  return id;
}

// One LCM instance's way out: the envelope, the copies, the sender's side of repair.
class Publisher {
 public:
  Publisher() : sender_(drawSenderId()) {}

  // The transport's own messages (repair requests, states) are neither kept
  // nor announced: nobody asks for them again.
  int publish(lcm::LCM& lcm, const std::string& channel, const void* data, std::size_t size) {
    const std::string_view base = wire::splitRunChannel(channel).base;
    const bool own = base == channels::kRepairRequest.name || base == channels::kSenderState.name;
    std::lock_guard<std::mutex> lock(mutex_);
    wire::Envelope envelope;
    envelope.sender = sender_;
    envelope.sequence = own ? ++own_sequence_ : kept_.nextSequence(channel);
    const int64_t now_us = wallMicros();
    envelope.stream_start_us = own ? now_us : kept_.streamStart(channel, now_us);
    const auto* payload = static_cast<const uint8_t*>(data);
    if (const MessageKey* key = processKey()) {
      envelope.tagged = true;
      envelope.tag = tagOf(*key, channel, envelope.sender, envelope.sequence, payload, size);
    }
    std::vector<uint8_t> bytes;
    bytes.reserve(size + wire::envelopeBytes(envelope.tagged));
    bytes.insert(bytes.end(), payload, payload + size);
    wire::appendEnvelope(bytes, envelope);
    const int status = lcm.publish(channel, bytes.data(), static_cast<unsigned>(bytes.size()));
    if (own) return status;
    kept_.keep(channel, envelope.sequence, std::move(bytes), envelope.stream_start_us);
    if (reliable_) reliable_->published();
    return status;
  }

  uint64_t sender() const { return sender_; }
  std::mutex& mutex() { return mutex_; }
  detail::RepairBuffer& kept() { return kept_; }
  void setReliable(detail::ReliableSender* reliable) { reliable_ = reliable; }

 private:
  const uint64_t sender_;
  std::mutex mutex_;
  detail::RepairBuffer kept_;
  detail::ReliableSender* reliable_ = nullptr;
  uint64_t own_sequence_ = 0;
};

struct Registry {
  std::mutex mutex;
  std::map<const lcm::LCM*, std::shared_ptr<Publisher>> publishers;
};

Registry& registry() {
  static Registry instance;
  return instance;
}

std::shared_ptr<Publisher> publisherOf(lcm::LCM& lcm) {
  Registry& all = registry();
  std::lock_guard<std::mutex> lock(all.mutex);
  auto& publisher = all.publishers[&lcm];
  if (!publisher) publisher = std::make_shared<Publisher>();
  return publisher;
}

class AttachedPublisher : public PublisherScope {
 public:
  // Long enough that a receiver starved of the CPU for a moment (a recorder
  // at lower priority on a busy machine) still asks in time.
  static constexpr int kLeaveQuietMs = 250, kLeaveLongestMs = 2000;

  AttachedPublisher(lcm::LCM& lcm, const std::string& url, const std::string& process)
      : lcm_(lcm), publisher_(publisherOf(lcm)) {
    detail::ReliableSender::Hooks hooks;
    hooks.sender = publisher_->sender();
    hooks.process = process;
    hooks.resend = [this](const std::string& channel, uint64_t sequence) { return resend(channel, sequence); };
    hooks.state = [this] {
      std::lock_guard<std::mutex> lock(publisher_->mutex());
      return publisher_->kept().state();
    };
    hooks.publish = [this](const std::string& channel, const std::vector<uint8_t>& encoded) {
      publishEncoded(lcm_, channel, encoded.data(), encoded.size());
    };
    reliable_ = detail::ReliableSender::startFor(url, std::move(hooks));
    std::lock_guard<std::mutex> lock(publisher_->mutex());
    publisher_->setReliable(reliable_.get());
  }
  ~AttachedPublisher() override {
    // Answer for the last messages a moment longer (reliable_sender.hpp).
    if (reliable_) reliable_->leave(kLeaveQuietMs, kLeaveLongestMs);
    {
      std::lock_guard<std::mutex> lock(publisher_->mutex());
      publisher_->setReliable(nullptr);
    }
    reliable_.reset();
    Registry& all = registry();
    std::lock_guard<std::mutex> lock(all.mutex);
    all.publishers.erase(&lcm_);
  }

 private:
  // Sends a kept message again, byte for byte; false when it is no longer kept.
  bool resend(const std::string& channel, uint64_t sequence) {
    std::shared_ptr<const std::vector<uint8_t>> bytes;
    {
      std::lock_guard<std::mutex> lock(publisher_->mutex());
      bytes = publisher_->kept().find(channel, sequence);
    }
    if (!bytes) return false;
    lcm_.publish(channel, bytes->data(), static_cast<unsigned>(bytes->size()));
    return true;
  }

  lcm::LCM& lcm_;
  std::shared_ptr<Publisher> publisher_;
  std::unique_ptr<detail::ReliableSender> reliable_;
};

}  // namespace

std::unique_ptr<PublisherScope> attachPublisher(lcm::LCM& lcm, const std::string& url, const std::string& process) {
  return std::make_unique<AttachedPublisher>(lcm, url, process);
}

int publishEncoded(lcm::LCM& lcm, const std::string& wire_channel, const void* data, std::size_t size) {
  return publisherOf(lcm)->publish(lcm, wire_channel, data, size);
}

uint64_t senderIdOf(lcm::LCM& lcm) { return publisherOf(lcm)->sender(); }

std::vector<Published> publishedOn(lcm::LCM& lcm) {
  const auto publisher = publisherOf(lcm);
  std::lock_guard<std::mutex> lock(publisher->mutex());
  std::vector<Published> published;
  for (const auto& channel : publisher->kept().state()) published.push_back({channel.channel, channel.last_sequence});
  return published;
}

uint64_t lastPublished(lcm::LCM& lcm, const std::string& wire_channel) {
  const auto publisher = publisherOf(lcm);
  std::lock_guard<std::mutex> lock(publisher->mutex());
  return publisher->kept().nextSequence(wire_channel) - 1;
}

}  // namespace beft::transport
