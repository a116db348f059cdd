// One way to write an expert (DESIGN.md, "Anatomy of an expert"): a class that
// declares what it reads and writes, stores messages in onMessage, computes
// and publishes only in fire(), and is driven by the arbiter's FIRE tokens.
// The same class runs live (run_expert.hpp) or offline against a log.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

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

// Named parameters from the command line (--param key=value) and defaults.
class Parameters {
 public:
  void set(const std::string& key, const std::string& value) { values_[key] = value; }
  bool has(const std::string& key) const { return values_.count(key) > 0; }
  const std::map<std::string, std::string>& all() const { return values_; }
  // Typed getters: the default when absent; std::invalid_argument naming the
  // key when the value does not parse.
  double getDouble(const std::string& key, double fallback) const;
  int64_t getInt(const std::string& key, int64_t fallback) const;
  bool getBool(const std::string& key, bool fallback) const;
  std::string getString(const std::string& key, const std::string& fallback) const;

 private:
  std::map<std::string, std::string> values_;
};

// Where fire() writes its outputs: live it publishes on LCM; in replay it
// collects them for comparison. Use publish<T>() with any generated LCM type.
class Output {
 public:
  virtual ~Output() = default;
  virtual void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) = 0;

  // publishEncoded gets bytes valid only during the call.
  template <typename Message>
  void publish(const std::string& channel, const Message& message) {
    // One buffer for every message: camera frames are tens of kB, and a
    // fresh buffer each time costs an allocation, zeroing and page faults.
    encoded_.resize(message.getEncodedSize());
    message.encode(encoded_.data(), 0, static_cast<int>(encoded_.size()));
    publishEncoded(channel, encoded_);
  }

 private:
  std::vector<uint8_t> encoded_;
};

class Expert {
 public:
  virtual ~Expert() = default;

  virtual std::string name() const = 0;         // default process name, e.g. "vision"
  virtual std::string description() const = 0;  // one paragraph for --help
  virtual std::vector<ChannelSpec> reads() const = 0;
  virtual std::vector<ChannelSpec> writes() const = 0;
  // Parameter names with their defaults and meaning, for --help and to report
  // unknown --param keys: {name, default, meaning}.
  virtual std::vector<std::vector<std::string>> parameterHelp() const { return {}; }

  // Called once before any message, with the parameters given. Throw
  // std::invalid_argument for a bad value: the process stops with that message.
  virtual void onStartUp(const Parameters& parameters) { (void)parameters; }
  // Store only, never compute. The bytes are an encoded message of the type
  // declared for the channel. Return false if the message was not understood
  // (it is then reported).
  virtual bool onMessage(const std::string& channel, const void* data, int size) = 0;
  // True when what this firing needs has arrived (e.g. the inputs of its tick).
  // The runner waits a bounded time for it, then fires anyway with a warning.
  virtual bool inputsReady(const Firing& firing) const { (void)firing; return true; }
  // Compute from what was stored, publish through out, say how it went.
  virtual Outcome fire(const Firing& firing, Output& out) = 0;
};

// Decodes an LCM message; false if the bytes are not a T.
template <typename Message>
bool decodeMessage(const void* data, int size, Message& message) {
  return message.decode(data, 0, size) == size;
}

}  // namespace beft::expert
