// How a process publishes: the one way out, as transport.hpp is the one way
// in. Every message gets an envelope (lib/wire/envelope.hpp: the process's
// sender id, its number on its channel and, in a run with a key, its tag); a
// copy is kept for a while so that a receiver that missed it can ask for it
// again; and on a udpm:// URL the process says what it has sent when it
// falls quiet (reliable_sender.hpp), so a receiver also learns of a lost
// last message. LCM still puts every datagram on the wire.
//
//   auto publishing = transport::attachPublisher(lcm, url, "vision");  // once, beside the LCM
//   transport::publish(lcm, wire::runChannel("VISION"), percepts);
//
// Without attachPublisher (unit tests on memq://), publish() still adds the
// envelope and keeps copies; nothing runs beside to serve them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <lcm/lcm-cpp.hpp>

namespace beft::transport {

class PublisherScope;

// Makes `lcm`'s publisher for a process named `process` on `url`: keeps
// copies for repair and, on udpm://, starts the thread that serves repair
// requests and sends the sender's states. Lives until the scope is
// destroyed, which must happen before `lcm` is. Throws std::runtime_error
// when the repair socket cannot be opened.
std::unique_ptr<PublisherScope> attachPublisher(lcm::LCM& lcm, const std::string& url, const std::string& process);

// Publishes encoded bytes on `wire_channel` (the name on the wire: with its
// run suffix, wire::runChannel). Returns what lcm::LCM::publish returns.
int publishEncoded(lcm::LCM& lcm, const std::string& wire_channel, const void* data, std::size_t size);

// Encodes `message` and publishes it as publishEncoded does.
template <typename Message>
int publish(lcm::LCM& lcm, const std::string& wire_channel, const Message& message) {
  thread_local std::vector<uint8_t> encoded;
  const int size = message.getEncodedSize();
  if (size < 0) return -1;
  encoded.resize(static_cast<std::size_t>(size));
  if (message.encode(encoded.data(), 0, size) != size) return -1;
  return publishEncoded(lcm, wire_channel, encoded.data(), encoded.size());
}

// This process's sender id on `lcm` (as its envelopes carry it).
uint64_t senderIdOf(lcm::LCM& lcm);

// What this process has published on `lcm`: the last sequence number on each
// channel (names as sent, with their run suffix).
struct Published {
  std::string channel;
  uint64_t sequence = 0;
};
std::vector<Published> publishedOn(lcm::LCM& lcm);
// The last sequence number published on `wire_channel` (0: nothing yet).
uint64_t lastPublished(lcm::LCM& lcm, const std::string& wire_channel);

class PublisherScope {
 public:
  virtual ~PublisherScope() = default;
};

}  // namespace beft::transport
