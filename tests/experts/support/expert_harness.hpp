// Drives an expert class without LCM: encodes messages into onMessage and
// collects what fire() publishes.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lib/expert/expert.hpp"

namespace beft::testing_support {

class CollectingOutput : public expert::Output {
 public:
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    published.emplace_back(channel, bytes);
  }
  // Every message published on a channel, decoded, oldest first.
  template <typename Message>
  std::vector<Message> on(const std::string& channel) const {
    std::vector<Message> out;
    for (const auto& [name, bytes] : published) {
      if (name != channel) continue;
      Message m;
      if (m.decode(bytes.data(), 0, static_cast<int>(bytes.size())) == static_cast<int>(bytes.size()))
        out.push_back(m);
    }
    return out;
  }
  void clear() { published.clear(); }
  std::vector<std::pair<std::string, std::vector<uint8_t>>> published;
};

template <typename Message>
bool deliver(expert::Expert& expert, const std::string& channel, const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return expert.onMessage(channel, bytes.data(), static_cast<int>(bytes.size()));
}

inline expert::Firing firing(const std::string& expert_name, int64_t tick, int64_t tick_us = 100000) {
  expert::Firing f;
  f.expert = expert_name;
  f.transition = "t_" + expert_name;
  f.tick = tick;
  f.utime = tick * tick_us;
  f.firing_id = tick + 1;
  return f;
}

}  // namespace beft::testing_support
