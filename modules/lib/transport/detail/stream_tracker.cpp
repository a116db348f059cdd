#include "lib/transport/detail/stream_tracker.hpp"

#include <algorithm>

#include "lib/wire/run_identity.hpp"

namespace beft::transport::detail {

namespace {

constexpr std::size_t kMostAskedAtOnce = 256;  // repair_request_t.count's bound

}  // namespace

StreamTracker::StreamTracker(Tracks tracks, Options options) : tracks_(std::move(tracks)), options_(options) {}

StreamTracker::Stream& StreamTracker::streamOf(uint64_t sender, std::string_view channel) {
  auto [at, made] = streams_.try_emplace(Key{sender, std::string(channel)});
  if (made) at->second.channel = std::string(channel);
  return at->second;
}

void StreamTracker::hear(uint64_t sender, int64_t now_us) {
  Sender& heard = senders_[sender];
  heard.last_heard_us = now_us;
  heard.dead = false;
}

// A stream's first number heard: one that began after this receiver
// started is taken from its first message (those before were lost on the
// way); an older one from here on.
void StreamTracker::start(Stream& stream, uint64_t first_heard, int64_t stream_start_us, int64_t now_us) {
  if (stream_start_us >= options_.listening_since_us) {
    stream.next = 1;
    if (first_heard > 1) markMissing(stream, 1, first_heard, now_us);
  } else {
    stream.next = first_heard;
    if (first_heard > 1) ++stats_.joined_late;
  }
}

void StreamTracker::markMissing(Stream& stream, uint64_t from, uint64_t to, int64_t now_us) {
  for (uint64_t sequence = from; sequence < to; ++sequence) {
    if (stream.held.count(sequence) || stream.missing.count(sequence)) continue;
    stream.missing[sequence] = Ask{now_us, std::max(options_.first_retry_us, 2 * round_trip_us_), 0};
    ++stats_.gaps;
  }
}

bool StreamTracker::holds(uint64_t sender, std::string_view channel, uint64_t sequence, int64_t now_us,
                          bool owed_unheard) {
  if (sequence == 0 || !tracks_(channel)) return true;
  if (!owed_unheard) {
    const auto known = streams_.find(Key{sender, std::string(channel)});
    if (known == streams_.end() || known->second.next == 0) return true;
  }
  const auto heard = senders_.find(sender);
  if (heard != senders_.end() && heard->second.dead) return true;
  if (heard == senders_.end()) hear(sender, now_us);  // its silence counts from now
  Stream& stream = streamOf(sender, channel);
  if (stream.next == 0) stream.next = sequence;  // known only from here: this one is wanted
  if (stream.next > sequence) return true;
  if (sequence - stream.next > options_.widest_gap) return true;  // not believed
  for (uint64_t awaited = stream.next; awaited <= sequence; ++awaited) {
    if (stream.held.count(awaited) || stream.missing.count(awaited)) continue;
    Ask ask{now_us + std::max(options_.in_flight_us, 2 * round_trip_us_),
            std::max(options_.first_retry_us, 2 * round_trip_us_), 0};
    ask.awaited = true;
    stream.missing[awaited] = ask;
  }
  return false;
}

void StreamTracker::filled(Stream& stream, uint64_t sequence, int64_t now_us) {
  const auto asked = stream.missing.find(sequence);
  if (asked == stream.missing.end()) return;
  // Awaited and come without being asked for: it was on its way, not lost.
  if (asked->second.awaited && asked->second.first_us == 0) {
    stream.missing.erase(asked);
    return;
  }
  ++stats_.repaired;
  if (asked->second.first_us > 0) {
    // The round trip, smoothed as TCP smooths its RTT (RFC 6298, alpha 1/8).
    const int64_t sample = std::max<int64_t>(now_us - asked->second.first_us, 100);
    round_trip_us_ += (sample - round_trip_us_) / 8;
  }
  stream.missing.erase(asked);
}

void StreamTracker::accept(const Message& message, const wire::Envelope& envelope, int64_t now_us,
                           const Handler& deliver) {
  hear(envelope.sender, now_us);
  Stream& stream = streamOf(envelope.sender, message.channel);
  const uint64_t sequence = envelope.sequence;
  if (sequence == 0) return;
  if (stream.next == 0) start(stream, sequence, envelope.stream_start_us, now_us);
  if (sequence < stream.next || stream.held.count(sequence)) {
    ++stats_.duplicates;
    return;
  }
  if (sequence - stream.next > options_.widest_gap) {
    ++stats_.implausible;
    return;
  }
  filled(stream, sequence, now_us);
  if (sequence == stream.next) {
    deliver(message);
    stream.handed_utime = std::max(stream.handed_utime, message.recv_utime);
    ++stream.next;
  } else {
    markMissing(stream, stream.next, sequence, now_us);
    if (options_.hand_on_at_once) {
      deliver(message);
      stream.held[sequence] = Held{{}, message.recv_utime, true};
    } else {
      stream.held[sequence] = Held{std::vector<uint8_t>(message.data, message.data + message.size), message.recv_utime};
    }
  }
  advance(envelope.sender, stream, false, deliver);
}

const char* StreamTracker::silentWhy(uint64_t sender) const {
  const auto heard = senders_.find(sender);
  return heard != senders_.end() && heard->second.leaving ? "its sender left before it came" : "its sender fell silent";
}

void StreamTracker::countLost(uint64_t sender, const Stream& stream, uint64_t sequence, const char* why) {
  ++stats_.lost;
  if (lost_named_.size() >= kMostLostNamed) return;
  const auto heard = senders_.find(sender);
  const std::string process =
      heard != senders_.end() && !heard->second.process.empty() ? heard->second.process : std::to_string(sender);
  lost_named_.push_back(std::string(wire::splitRunChannel(stream.channel).base) + " #" + std::to_string(sequence) +
                        " of " + process + " (" + why + ")");
}

// Hands on what is held in order; skips what is given up (no longer kept,
// or, when the sender is dead, anything before what is held).
void StreamTracker::advance(uint64_t sender, Stream& stream, bool sender_dead, const Handler& deliver) {
  for (;;) {
    if (!stream.held.empty() && stream.held.begin()->first == stream.next && stream.held.begin()->second.handed) {
      stream.held.erase(stream.held.begin());
      ++stream.next;
      continue;
    }
    if (!stream.held.empty() && stream.held.begin()->first == stream.next) {
      auto held = stream.held.begin();
      Message message;
      message.channel = stream.channel;
      message.data = held->second.bytes.data();
      message.size = held->second.bytes.size();
      // Handed on when the gap before it was filled: received, for whoever
      // orders by receive time (the recorder), after what filled it.
      message.recv_utime = std::max(held->second.recv_utime, stream.handed_utime);
      stream.handed_utime = message.recv_utime;
      deliver(message);
      stream.held.erase(held);
      ++stream.next;
      continue;
    }
    const bool no_longer_kept = stream.next < stream.gone_below;
    if (!no_longer_kept && !(sender_dead && !stream.held.empty())) break;
    if (stream.missing.erase(stream.next))
      countLost(sender, stream, stream.next, no_longer_kept ? "no longer kept by its sender" : silentWhy(sender));
    ++stream.next;
  }
  if (sender_dead) {
    for (const auto& [sequence, ask] : stream.missing) countLost(sender, stream, sequence, silentWhy(sender));
    stream.missing.clear();
  }
}

void StreamTracker::onState(const beft::sender_state_t& state, int64_t now_us, const Handler& deliver) {
  const auto sender = static_cast<uint64_t>(state.sender);
  hear(sender, now_us);
  senders_[sender].leaving = state.leaving;
  senders_[sender].process = state.process;
  const std::size_t count = std::min({state.channels.size(), state.last_sequences.size(), state.first_kept.size(),
                                      state.stream_started.size()});
  for (std::size_t i = 0; i < count; ++i) {
    if (!tracks_(state.channels[i]) || state.last_sequences[i] < 1) continue;
    const auto last = static_cast<uint64_t>(state.last_sequences[i]);
    Stream& stream = streamOf(sender, state.channels[i]);
    if (stream.next == 0) {
      const int64_t started = state.stream_started[i];
      if (started < options_.listening_since_us) {
        stream.next = last + 1;  // came late: nothing of it is this receiver's business
        ++stats_.joined_late;
        continue;
      }
      stream.next = 1;
    }
    if (last >= stream.next && last - stream.next <= options_.widest_gap) markMissing(stream, stream.next, last + 1, now_us);
    stream.gone_below = std::max<uint64_t>(stream.gone_below, static_cast<uint64_t>(std::max<int64_t>(0, state.first_kept[i])));
    advance(sender, stream, false, deliver);
  }
}

std::vector<beft::repair_request_t> StreamTracker::due(int64_t now_us, const Handler& deliver) {
  std::vector<beft::repair_request_t> requests;
  for (auto& [key, stream] : streams_) {
    if (stream.missing.empty()) continue;
    Sender& sender = senders_[key.first];
    if (now_us - sender.last_heard_us > silenceAllowed(sender)) {
      sender.dead = true;
      advance(key.first, stream, true, deliver);
      continue;
    }
    beft::repair_request_t request;
    request.sender = static_cast<int64_t>(key.first);
    request.channel = stream.channel;
    for (auto& [sequence, ask] : stream.missing) {
      if (ask.next_us > now_us) continue;
      if (request.sequences.size() >= kMostAskedAtOnce) break;
      request.sequences.push_back(static_cast<int64_t>(sequence));
      if (ask.first_us == 0) {
        ask.first_us = now_us;
        if (ask.awaited) ++stats_.gaps;  // awaited, and still not here: lost
      }
      const int64_t slowest = sender.leaving ? options_.slowest_retry_of_leaving_us : options_.slowest_retry_us;
      ask.next_us = now_us + std::min(ask.wait_us, slowest);
      ask.wait_us = std::min(ask.wait_us * 2, slowest);
    }
    if (request.sequences.empty()) continue;
    request.count = static_cast<int32_t>(request.sequences.size());
    ++stats_.requests;
    requests.push_back(std::move(request));
  }
  return requests;
}

int64_t StreamTracker::nextDueUs() const {
  int64_t next = std::numeric_limits<int64_t>::max();
  for (const auto& [key, stream] : streams_) {
    if (stream.missing.empty()) continue;
    for (const auto& [sequence, ask] : stream.missing) next = std::min(next, ask.next_us);
    const auto sender = senders_.find(key.first);
    if (sender != senders_.end())
      next = std::min(next, sender->second.last_heard_us + silenceAllowed(sender->second) + 1);
  }
  return next;
}

std::size_t StreamTracker::heldMessages() const {
  std::size_t held = 0;
  for (const auto& [key, stream] : streams_)
    for (const auto& [sequence, message] : stream.held) held += message.handed ? 0 : 1;
  return held;
}

std::size_t StreamTracker::missingMessages() const {
  std::size_t missing = 0;
  for (const auto& [key, stream] : streams_) missing += stream.missing.size();
  return missing;
}

}  // namespace beft::transport::detail
