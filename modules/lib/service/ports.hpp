// A service's inputs and outputs, each declared once as a member:
//
//   service::ReadPort<plan_request_t> requests_in_{*this, channels::kPlanRequest, "each answered once",
//                                                  [this](plan_request_t&& request) { ... }};
//   service::WritePort<plan_result_t> results_out_{*this, channels::kPlanResult};
//
// From the ports come --interface (reads(), writes()), what the process's
// receivers take (selection(): on the run's channel names, with kernel
// filters) and how a received message reaches its handler (dispatch():
// decoded through the guard, a refusal counted under its channel, as an
// expert's ports do, lib/expert/ports.hpp).
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/transport/transport.hpp"
#include "lib/wire/decoding_handler.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::service {

// A channel a service reads or writes, with what it does with it (--interface).
struct Port {
  std::string channel;
  std::string type;  // e.g. "beft.done_t"
  std::string note;  // e.g. "an expert finished a firing"
};

// Which run's traffic a port takes or writes.
enum class Reach {
  kRun,       // this process's run: "DONE@<run>" (wire::runChannel)
  kUrlWide,   // every run on the URL, under the bare name (BEFT_RUNS beacons)
  kEveryRun,  // every run's channels, under the names heard (the recorder)
};

// Whether a port's messages wake the process, or wait in the kernel until
// it reads them with what woke it (transport.hpp, openSplitReceivers).
enum class Delivery { kWakes, kQueued };

// How a read port receives; by default every message of its channel, on the
// run, waking the process.
struct Receiving {
  Delivery delivery = Delivery::kWakes;
  Reach reach = Reach::kRun;
  std::vector<transport::Rule> rules;  // only these messages of the channel (control_messages.hpp); empty: all
  bool also_to_every_channel = false;  // handed to the port of every channel too (the blackboard keeps it)

  Receiving& queued() {
    delivery = Delivery::kQueued;
    return *this;
  }
  Receiving& urlWide() {
    reach = Reach::kUrlWide;
    return *this;
  }
  Receiving& everyRun() {
    reach = Reach::kEveryRun;
    return *this;
  }
  Receiving& only(transport::Rule rule) {
    rules.push_back(std::move(rule));
    return *this;
  }
  Receiving& alsoToEveryChannel() {
    also_to_every_channel = true;
    return *this;
  }
};

class ReadPortBase;
class WritePortBase;

// The ports of a service (or of a part of one, include()d by it).
class PortSet {
 public:
  PortSet() = default;
  virtual ~PortSet() = default;
  // Ports point at their set: never copied.
  PortSet(const PortSet&) = delete;
  PortSet& operator=(const PortSet&) = delete;

  // What it reads and writes, in the order declared (included parts after its own).
  std::vector<Port> reads() const;
  std::vector<Port> writes() const;
  // Lists and dispatches the ports of `part` as its own.
  void include(PortSet& part) { parts_.push_back(&part); }

  // What a receiver takes for the ports of `delivery`: their channels (with
  // their rules), or, with a port of every channel among them, everything
  // but what that port leaves out (std::logic_error if a port beside it has
  // rules: they would narrow nothing). Empty (AcceptListed, no rules) if none.
  transport::Selection selection(Delivery delivery) const;
  // Hands a received message (under its plain channel name) to the port of
  // its channel, else to the port of every channel. False if no port took
  // it or the port refused it (counted under the channel by the guard).
  bool dispatch(const transport::Message& message) const;

 private:
  friend class ReadPortBase;
  friend class WritePortBase;
  std::vector<const ReadPortBase*> allReaders() const;
  // The port of `channel` and the port of every channel, where declared (no allocation: on every message's path).
  void findReaders(std::string_view channel, const ReadPortBase*& named, const ReadPortBase*& every_channel) const;
  std::vector<ReadPortBase*> readers_;
  std::vector<const WritePortBase*> writers_;
  std::vector<PortSet*> parts_;
};

class ReadPortBase {
 public:
  // Throws std::logic_error if `reach` says URL-wide of a channel the
  // transport names by run, or the other way round.
  ReadPortBase(PortSet& owner, std::string channel, std::string type, std::string note, Receiving receiving);
  virtual ~ReadPortBase() = default;
  ReadPortBase(const ReadPortBase&) = delete;
  ReadPortBase& operator=(const ReadPortBase&) = delete;

  const std::string& channel() const { return channel_; }
  const Receiving& receiving() const { return receiving_; }
  virtual Port described() const;
  // The port of every channel (at most one per delivery).
  virtual bool everyChannel() const { return false; }
  // What a receiver takes for it (for the port of every channel: what it leaves out).
  virtual std::vector<transport::Rule> rules() const;
  // Hands one received message on; false if it was refused.
  virtual bool receive(const transport::Message& message) const = 0;

 protected:
  std::string channel_;  // an answer port's is named when the process knows its name

 private:
  std::string type_;
  std::string note_;
  Receiving receiving_;
};

// Each message decoded through the guard and handed to `handler`.
template <typename Message>
class ReadPort : public ReadPortBase {
 public:
  using Handler = typename wire::DecodingHandler<Message>::Handler;
  ReadPort(PortSet& owner, channels::Channel<Message> channel, std::string note, Handler handler,
           Receiving receiving = {})
      : ReadPortBase(owner, channel.name, channel.typeName(), std::move(note), std::move(receiving)),
        handler_(std::move(handler)) {}
  bool receive(const transport::Message& message) const override {
    return handler_(channel(), message.data, message.size);
  }

 private:
  wire::DecodingHandler<Message> handler_;
};

// Each message checked by the guard and handed on as bytes, to be decoded
// when needed (the planner keeps a few seconds of maps and decodes the one a
// request needs).
template <typename Message>
class CheckedBytesPort : public ReadPortBase {
 public:
  using Handler = std::function<void(const transport::Message&)>;
  CheckedBytesPort(PortSet& owner, channels::Channel<Message> channel, std::string note, Handler handler,
                   Receiving receiving = {})
      : ReadPortBase(owner, channel.name, channel.typeName(), std::move(note), std::move(receiving)),
        handler_(std::move(handler)) {}
  bool receive(const transport::Message& message) const override {
    if (!wire::validFrom<Message>(channel(), message.data, message.size)) return false;
    handler_(message);
    return true;
  }
  // Decodes bytes it handed on; a refusal is counted under its channel.
  bool decode(const std::vector<uint8_t>& bytes, Message& message) const {
    return wire::decodeFrom(channel(), bytes.data(), bytes.size(), message);
  }

 private:
  Handler handler_;
};

// The answers to this process's requests, on a channel named after it
// (BB_SNAPSHOT_<requester>): takes nothing until answerOn names it.
template <typename Message>
class AnswerPort : public ReadPort<Message> {
 public:
  AnswerPort(PortSet& owner, channels::Channel<Message> prefix, std::string note,
             typename ReadPort<Message>::Handler handler)
      : ReadPort<Message>(owner, prefix, std::move(note), std::move(handler)), prefix_(prefix.name) {
    this->channel_ = prefix_ + "<requester>";
  }
  // Throws std::logic_error if `channel` does not start with the prefix.
  void answerOn(const std::string& channel) {
    if (channel.compare(0, prefix_.size(), prefix_) != 0)
      throw std::logic_error("answers on " + channel + ", not a " + prefix_ + "* channel");
    this->channel_ = channel;
    named_ = true;
  }
  std::vector<transport::Rule> rules() const override {
    return named_ ? ReadPort<Message>::rules() : std::vector<transport::Rule>{};
  }

 private:
  std::string prefix_;
  bool named_ = false;
};

// Every channel but those it leaves out (the blackboard, the recorder),
// handed on as bytes. `left_out`, when given, lists channel patterns not
// taken; the plain names among them are dropped in the kernel.
class EveryChannelPort : public ReadPortBase {
 public:
  using Handler = std::function<void(const transport::Message&)>;
  EveryChannelPort(PortSet& owner, std::string note, Handler handler, Receiving receiving = {},
                   const std::vector<std::string>* left_out = nullptr);
  Port described() const override;
  bool everyChannel() const override { return true; }
  std::vector<transport::Rule> rules() const override;
  bool receive(const transport::Message& message) const override;

 private:
  Handler handler_;
  const std::vector<std::string>* left_out_;
};

class WritePortBase {
 public:
  // Throws std::logic_error as ReadPortBase does.
  WritePortBase(PortSet& owner, std::string channel, std::string type, std::string note, Reach reach);
  WritePortBase(const WritePortBase&) = delete;
  WritePortBase& operator=(const WritePortBase&) = delete;
  const std::string& channel() const { return channel_; }
  Port described() const;
  // The name published under: the run's (wire::runChannel), or the bare one if URL-wide.
  const std::string& wireName() const { return names_.of(channel_); }

 protected:
  std::string channel_;

 private:
  std::string type_;
  std::string note_;
  Reach reach_;
  mutable wire::RunChannelNames names_;
};

template <typename Message>
class WritePort : public WritePortBase {
 public:
  WritePort(PortSet& owner, channels::Channel<Message> channel, std::string note = "", Reach reach = Reach::kRun)
      : WritePortBase(owner, channel.name, channel.typeName(), std::move(note), reach) {}
  // LCM's status: 0 when sent.
  int publish(lcm::LCM& lcm, const Message& message) const { return transport::publish(lcm, wireName(), message); }
};

// Answers on a channel named after the requester (BB_SNAPSHOT_<requester>).
template <typename Message>
class AnswerWritePort : public WritePortBase {
 public:
  AnswerWritePort(PortSet& owner, channels::Channel<Message> prefix, std::string note)
      : WritePortBase(owner, std::string(prefix.name) + "<requester>", prefix.typeName(), std::move(note),
                      Reach::kRun),
        prefix_(prefix.name) {}
  // On `channel`, in this run. Throws std::logic_error if it lacks the prefix.
  int publish(lcm::LCM& lcm, const std::string& channel, const Message& message) const {
    if (channel.compare(0, prefix_.size(), prefix_) != 0)
      throw std::logic_error("an answer on " + channel + ", not a " + prefix_ + "* channel");
    return transport::publish(lcm, wire::runChannel(channel), message);
  }

 private:
  std::string prefix_;
};

}  // namespace beft::service
