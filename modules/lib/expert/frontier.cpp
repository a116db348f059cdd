#include "lib/expert/frontier.hpp"

#include <algorithm>

#include "lib/common/channels.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::expert {

namespace {

bool allHold(std::initializer_list<transport::Receiver*> receivers, uint64_t sender, const std::string& channel,
             uint64_t sequence, bool restarted) {
  bool held = true;
  // Every receiver is asked (each asks for what it misses), not just the first that lacks it.
  for (transport::Receiver* receiver : receivers)
    if (receiver != nullptr && !receiver->holds(sender, channel, sequence, !restarted)) held = false;
  return held;
}

}  // namespace

void Frontier::add(const beft::frontier_t& frontier) {
  const std::size_t count =
      std::min({frontier.senders.size(), frontier.channels.size(), frontier.sequences.size()});
  for (std::size_t i = 0; i < count; ++i) {
    int64_t& latest = latest_[{frontier.senders[i], frontier.channels[i]}];
    latest = std::max(latest, frontier.sequences[i]);
  }
}

bool Frontier::reached(const beft::fire_t& fire, std::initializer_list<transport::Receiver*> receivers,
                       bool restarted) const {
  if (fire.after_frontier <= 0) return true;
  if (!allHold(receivers, static_cast<uint64_t>(fire.after_sender), channels::kFrontier.name,
               static_cast<uint64_t>(fire.after_frontier), restarted))
    return false;
  bool held = true;
  for (const auto& [where, sequence] : latest_)
    if (sequence > 0 && !allHold(receivers, static_cast<uint64_t>(where.first), where.second,
                                 static_cast<uint64_t>(sequence), restarted))
      held = false;
  return held;
}

void listPublished(lcm::LCM& lcm, beft::done_t& done) {
  done.sender = static_cast<int64_t>(transport::senderIdOf(lcm));
  done.published_channels.clear();
  done.published_sequences.clear();
  for (const auto& published : transport::publishedOn(lcm)) {
    const std::string base(wire::splitRunChannel(published.channel).base);
    if (!channels::isDataPlaneChannel(base)) continue;
    done.published_channels.push_back(base);
    done.published_sequences.push_back(static_cast<int64_t>(published.sequence));
  }
  done.num_published = static_cast<int32_t>(done.published_channels.size());
}

}  // namespace beft::expert
