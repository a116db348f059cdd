// One way to write an expert (DESIGN.md, "Anatomy of an expert"): a class
// that declares its inputs and outputs as port members (ports.hpp) and its
// parameters in declareParameters, stores messages through its ports,
// computes and publishes only in fire(), and is driven by the arbiter's FIRE
// tokens. The same class runs live (run_expert.hpp) or offline against a log.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "lib/common/channels.hpp"
#include "lib/common/declared_parameters.hpp"
#include "lib/expert/ports.hpp"

namespace beft::expert {

// One FIRE token from the arbiter.
struct Firing {
  std::string expert;      // expert name the token is for
  std::string transition;  // Petri-net transition id
  int64_t tick = 0;        // tick index k
  int64_t utime = 0;       // simulated time of the tick [us]
  int64_t firing_id = 0;   // unique, only grows
};

struct Outcome {
  bool ok = true;
  std::string message;  // why it failed, or empty
  static Outcome success() { return {}; }
  static Outcome failure(std::string why) { return {false, std::move(why)}; }
};

// A channel and the LCM type carried on it, for --interface and subscriptions.
struct ChannelSpec {
  std::string channel;
  std::string type;  // e.g. "beft.robot_state_t"
};

// Parameter values given on the command line (--param NAME=VALUE), by name.
using Parameters = std::map<std::string, std::string>;

// Where fire() writes its outputs: live it publishes on LCM; in replay it
// collects them for comparison. Only channels the expert declared an
// OutputPort for can be published on (once the runner has told it which).
class Output {
 public:
  virtual ~Output() = default;
  // publishEncoded gets bytes valid only during the call.
  virtual void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) = 0;

  // From here on, a publish on any other channel throws std::logic_error.
  void restrictTo(const std::vector<ChannelSpec>& declared);

  template <typename Message>
  void publish(channels::Channel<Message> channel, const Message& message) {
    if (!declared_.empty() && !declared_.count(channel.name))
      throw std::logic_error(std::string("publish on ") + channel.name + ", which the expert does not declare");
    // One buffer for every message: camera frames are tens of kB, and a
    // fresh buffer each time costs an allocation, zeroing and page faults.
    encoded_.resize(message.getEncodedSize());
    message.encode(encoded_.data(), 0, static_cast<int>(encoded_.size()));
    publishEncoded(channel.name, encoded_);
  }

 private:
  std::vector<uint8_t> encoded_;
  std::set<std::string> declared_;
};

template <typename Message>
void OutputPort<Message>::publish(Output& out, const Message& message) const {
  out.publish(channels::Channel<Message>{channel()}, message);
}

class Expert {
 public:
  Expert() = default;
  virtual ~Expert() = default;
  // Ports point at their expert: never copied.
  Expert(const Expert&) = delete;
  Expert& operator=(const Expert&) = delete;

  virtual std::string name() const = 0;         // default process name, e.g. "vision"
  virtual std::string description() const = 0;  // one paragraph for --help

  // What it reads and writes, from its ports, in the order declared; once
  // started up, the inputs it left unread as configured are not listed
  // (InputPortBase::setRead).
  std::vector<ChannelSpec> reads() const;
  std::vector<ChannelSpec> writes() const;

  // Its parameters with defaults, ranges and meanings (declared once).
  const DeclaredParameters& parameters();
  // Sets the parameters given (every other one back to its default) and
  // calls onStartUp. std::invalid_argument for an unknown name, a value out
  // of its range, or what onStartUp refuses.
  void startUp(const Parameters& given = {});

  // Hands a received message to the port that reads its channel (store
  // only, never compute). False if no port reads the channel or the bytes
  // are not a message of its type (the runner reports it).
  bool onMessage(const std::string& channel, const void* data, int size);

  // True when what this firing needs has arrived; by default, when no
  // declared input lacks the firing's tick (inputsLacking). Override only to
  // add conditions (a planner's answer) or to read some input otherwise.
  // The runner waits a bounded time for it, then fires anyway with a warning.
  virtual bool inputsReady(const Firing& firing) const;
  // The channels read by tick that hold nothing of the firing's tick.
  std::vector<std::string> inputsLacking(const Firing& firing) const;
  // Compute from what was stored, publish through out, say how it went.
  virtual Outcome fire(const Firing& firing, Output& out) = 0;

 protected:
  // Declare each parameter: parameters.declare("name", member_, min, max, "meaning").
  virtual void declareParameters(DeclaredParameters& parameters) { (void)parameters; }
  // Called by startUp with the parameters set: check what the ranges do not
  // (relations between parameters), build the logic. Throw
  // std::invalid_argument for a bad value: the process stops with that message.
  virtual void onStartUp() {}

 private:
  friend class InputPortBase;
  friend class OutputPortBase;
  std::vector<InputPortBase*> inputs_;
  std::vector<OutputPortBase*> outputs_;
  std::unique_ptr<DeclaredParameters> parameters_;
};

}  // namespace beft::expert
