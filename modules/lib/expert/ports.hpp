// An expert's inputs and outputs, each declared once as a member:
//
//   expert::TickInput<visual_percepts_t> vision_{*this, channels::kVision};
//   expert::OutputPort<hypotheses_t> hypotheses_out_{*this, channels::kHypotheses};
//
// A port registers itself with its expert; the channel's type comes from the
// channel table (channels.hpp). What the expert reads and writes
// (--interface, subscriptions, kernel filters, replay) and how a received
// message reaches its store are derived from the ports, and decoding happens
// here, in one place.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include "lib/wire/channel_history.hpp"
#include "lib/common/channels.hpp"
#include "lib/wire/decoding_handler.hpp"
#include "lib/wire/guarded_decode.hpp"

namespace beft::expert {

class Expert;
class Output;

// Decodes a received message through the guard (wire/guarded_decode.hpp);
// false, counted under the channel, if the bytes are not exactly one valid
// Message.
template <typename Message>
bool decodeMessage(const std::string& channel, const void* data, int size, Message& message) {
  return size >= 0 && wire::decodeFrom(channel, data, static_cast<std::size_t>(size), message);
}

class InputPortBase {
 public:
  InputPortBase(Expert& owner, const char* channel, std::string type);
  virtual ~InputPortBase() = default;
  InputPortBase(const InputPortBase&) = delete;
  InputPortBase& operator=(const InputPortBase&) = delete;

  const char* channel() const { return channel_; }
  const std::string& type() const { return type_; }
  // Decodes and keeps one received message; false if the bytes are not one.
  virtual bool receive(const void* data, int size) = 0;
  // Whether the port keeps inputs by tick and has none of this one (what a
  // firing of that tick lacks; replay reports it).
  virtual bool lacksTick(int64_t tick) const {
    (void)tick;
    return false;
  }
  // The channel to ask the blackboard for when lacksTick (usually its own).
  virtual std::string lackingChannel(int64_t tick) const {
    (void)tick;
    return channel_;
  }

  // An input the expert has no use for as configured (called from its
  // onStartUp, e.g. the ear signals when it does not hear): the channel is
  // left out of reads(), so it is neither subscribed to nor decoded, and no
  // firing waits for it. Expert::startUp reads every port again first.
  virtual void setRead(bool read) { read_ = read; }
  bool isRead() const { return read_; }

 private:
  const char* channel_;
  std::string type_;
  bool read_ = true;
};

// Messages kept by the tick they belong to (every type an expert reads this
// way carries `utime` and `tick`), looked up by the tick a firing is for.
// admit, when given, checks each decoded message before it is kept and may
// unpack it in place (a camera frame's pixels); a message it refuses is
// counted under the channel like the guard's refusals, with its reason.
template <typename Message>
class TickInput : public InputPortBase {
 public:
  using Admit = std::function<bool(Message& message, std::string* why)>;
  // optional_until_heard: an input older logs lack; nothing is missing until one was heard.
  TickInput(Expert& owner, channels::Channel<Message> channel, std::size_t capacity = 16, Admit admit = {},
            bool optional_until_heard = false)
      : InputPortBase(owner, channel.name, channel.typeName()),
        history_(capacity),
        admit_(std::move(admit)),
        optional_until_heard_(optional_until_heard) {}

  bool receive(const void* data, int size) override {
    // Decoded over the message the history dropped last (every field is
    // written), so its strings and arrays keep their storage.
    if (!decodeMessage(channel(), data, size, spare_)) return false;
    std::string why;
    if (admit_ && !admit_(spare_, &why)) {
      wire::processRejects().count(channel(), {wire::Fault::kBadPayload, ""}, why);
      return false;
    }
    const int64_t utime = spare_.utime;
    history_.store(std::move(spare_), utime, &spare_);  // moved: a camera frame's pixels are not copied again
    return true;
  }
  void store(const Message& message) { history_.store(message, message.utime); }

  // The newest stored message of tick k, or null. Walks back one simulated
  // time at a time (utime strictly falls), so it ends on any history.
  const Message* ofTick(int64_t tick) const {
    for (const auto* entry = history_.latest(); entry != nullptr; entry = history_.atOrBefore(entry->utime - 1)) {
      if (entry->message.tick == tick) return &entry->message;
    }
    return nullptr;
  }
  const Message* latest() const {
    const auto* newest = history_.latest();
    return newest == nullptr ? nullptr : &newest->message;
  }
  bool has(int64_t tick) const { return ofTick(tick) != nullptr; }
  bool empty() const { return history_.empty(); }
  bool lacksTick(int64_t tick) const override {
    return !(optional_until_heard_ && empty()) && !has(tick - ticks_before_);
  }
  // A firing of tick k reads the message of tick k - 1: an input published
  // later in each tick than the expert fires (lacksTick asks for that one).
  void readTheTickBefore() { ticks_before_ = 1; }

 private:
  blackboard::ChannelHistory<Message> history_;
  int64_t ticks_before_ = 0;
  Message spare_{};  // what the next message is decoded over
  Admit admit_;
  bool optional_until_heard_ = false;
};

// Each message handed, decoded, to a handler of the expert's (a queue of
// commands, a state to resume from). `wanted`, when given, is asked first:
// a message not wanted is not decoded (an expert's own output heard back).
template <typename Message>
class HandledInput : public InputPortBase {
 public:
  using Handler = typename wire::DecodingHandler<Message>::Handler;
  HandledInput(Expert& owner, channels::Channel<Message> channel, Handler handler,
               std::function<bool()> wanted = {})
      : InputPortBase(owner, channel.name, channel.typeName()),
        handler_(std::move(handler)),
        wanted_(std::move(wanted)) {}

  bool receive(const void* data, int size) override {
    if (wanted_ && !wanted_()) return true;
    return size >= 0 && handler_(channel(), data, static_cast<std::size_t>(size));
  }

 private:
  wire::DecodingHandler<Message> handler_;
  std::function<bool()> wanted_;
};

class OutputPortBase {
 public:
  OutputPortBase(Expert& owner, const char* channel, std::string type);
  OutputPortBase(const OutputPortBase&) = delete;
  OutputPortBase& operator=(const OutputPortBase&) = delete;
  const char* channel() const { return channel_; }
  const std::string& type() const { return type_; }

 private:
  const char* channel_;
  std::string type_;
};

template <typename Message>
class OutputPort : public OutputPortBase {
 public:
  OutputPort(Expert& owner, channels::Channel<Message> channel)
      : OutputPortBase(owner, channel.name, channel.typeName()) {}
  void publish(Output& out, const Message& message) const;
};

}  // namespace beft::expert
