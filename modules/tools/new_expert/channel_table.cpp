#include "tools/new_expert/channel_table.hpp"

#include <type_traits>
#include <utility>

#include "lib/common/channels.hpp"

namespace beft::new_expert {

namespace {

template <typename Message, typename = void>
struct HasUtime : std::false_type {};
template <typename Message>
struct HasUtime<Message, std::void_t<decltype(std::declval<Message>().utime)>> : std::true_type {};

template <typename Message, typename = void>
struct HasTick : std::false_type {};
template <typename Message>
struct HasTick<Message, std::void_t<decltype(std::declval<Message>().tick)>> : std::true_type {};

}  // namespace

const std::vector<KnownChannel>& knownChannels() {
  // Variadic: a column added after the type (a channel's plane, say) is ignored.
#define BEFT_KNOWN_CHANNEL(constant, name, type, ...) \
  KnownChannel{#constant, name, #type, HasUtime<type>::value, HasTick<type>::value},
  static const std::vector<KnownChannel> table = {BEFT_CHANNELS(BEFT_KNOWN_CHANNEL)};
#undef BEFT_KNOWN_CHANNEL
  return table;
}

const KnownChannel* findChannel(const std::string& name) {
  for (const auto& channel : knownChannels())
    if (channel.name == name) return &channel;
  return nullptr;
}

std::string channelNames() {
  std::string names;
  for (const auto& channel : knownChannels()) names += (names.empty() ? "" : ", ") + channel.name;
  return names;
}

}  // namespace beft::new_expert
