// The receiver's side of loss repair: every (sender, channel) a receiver
// takes is a stream numbered from 1 (the envelope's sequence number). A gap
// in the numbers, or a sender's state (BEFT_SENDERS) that names a message not
// yet heard, is a loss: it is asked for (a repair request, the NACK of PGM
// and NORM) at once, then again after a back-off sized to the measured round
// trip, as long as the sender is heard. Messages after a gap are held and
// handed on in order once it is filled, so a handler sees each stream
// complete, in order and once. A gap is given up only when its sender says
// the message is no longer kept, or falls silent (dead): then what was held
// goes on, and the loss is counted.
//
// A stream that began before the receiver started listening is taken from
// where it is first heard: what came before is not this receiver's business
// (a process restarted mid-run restores its state from the run's log).
//
// Pure logic with the time passed in, so the tests drive it message by message.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <beft/repair_request_t.hpp>
#include <beft/sender_state_t.hpp>

#include "lib/transport/transport.hpp"
#include "lib/wire/envelope.hpp"

namespace beft::transport::detail {

class StreamTracker {
 public:
  struct Options {
    int64_t dead_after_us = 3'000'000;    // a sender not heard for this long is given up
    int64_t left_after_us = 500'000;      // one that said it is leaving, this long after it last spoke
    int64_t first_retry_us = 1'000;       // shortest wait before asking again
    int64_t in_flight_us = 500;           // shortest wait for an awaited message before asking for it
    int64_t slowest_retry_us = 250'000;   // longest wait between asks
    // Longest wait between asks of a sender that said it is leaving: well
    // within the quiet time it still answers for (publisher.cpp).
    int64_t slowest_retry_of_leaving_us = 25'000;
    // When this receiver started listening [us since the epoch]: a stream
    // that began after it is asked for from its first message; one that
    // began before is taken from where it is first heard (a late joiner).
    int64_t listening_since_us = 0;
    // Hand on what comes after a gap at once rather than hold it (a
    // recorder: its log is ordered by time, and a message held behind the
    // gap of a killed sender would be written only when that sender is
    // given up, after its restarted process looked for it in the log).
    bool hand_on_at_once = false;
    uint64_t widest_gap = 65'536;         // a jump further than this is not believed (a damaged envelope)
  };
  // Whether the receiver takes a channel (as sent, with its run suffix) as a stream.
  using Tracks = std::function<bool(std::string_view channel)>;

  StreamTracker(Tracks tracks, Options options);
  explicit StreamTracker(Tracks tracks) : StreamTracker(std::move(tracks), Options{}) {}

  bool tracks(std::string_view channel) const { return tracks_(channel); }

  // A message with its envelope on a tracked channel (`message` without the
  // envelope): handed to `deliver` now, with any it completes, or held, or
  // dropped as a copy already had.
  void accept(const Message& message, const wire::Envelope& envelope, int64_t now_us, const Handler& deliver);
  // Whether message `sequence` of `sender` on `channel` has been handed on
  // (or never will be: a channel not tracked, a sender given up). When not,
  // it and what comes before it are awaited, and asked for after a short
  // wait (it is most likely on its way).
  // `owed_unheard` false: a stream never heard is not awaited (a receiver
  // of a process restarted mid-run).
  bool holds(uint64_t sender, std::string_view channel, uint64_t sequence, int64_t now_us, bool owed_unheard = true);
  // A sender's state: a last message not heard is a loss; a gap no longer
  // kept is given up.
  void onState(const beft::sender_state_t& state, int64_t now_us, const Handler& deliver);
  // The repair requests due at `now_us` (one per stream), and gives up on
  // senders not heard for dead_after_us.
  std::vector<beft::repair_request_t> due(int64_t now_us, const Handler& deliver);
  // When due() next has something to do [us]; max() when nothing waits.
  int64_t nextDueUs() const;

  struct Stats {
    uint64_t gaps = 0;         // messages found missing
    uint64_t repaired = 0;     // of those, got later
    uint64_t lost = 0;         // of those, given up
    uint64_t duplicates = 0;   // copies dropped
    uint64_t joined_late = 0;  // streams first heard after their early messages were gone
    uint64_t implausible = 0;  // envelopes whose number jumped too far, dropped
    uint64_t requests = 0;     // repair requests sent
  };
  // The first kMostLostNamed messages given up, each as "CHANNEL #N of
  // PROCESS (why)": what a log that is not complete lacks.
  static constexpr std::size_t kMostLostNamed = 8;
  const Stats& stats() const { return stats_; }
  const std::vector<std::string>& lostNamed() const { return lost_named_; }
  int64_t roundTripUs() const { return round_trip_us_; }
  std::size_t heldMessages() const;
  std::size_t missingMessages() const;

 private:
  struct Held {
    std::vector<uint8_t> bytes;
    int64_t recv_utime = 0;
    bool handed = false;  // already handed on (hand_on_at_once): only its number is kept
  };
  struct Ask {
    int64_t next_us = 0;     // when to ask (again)
    int64_t wait_us = 0;     // the wait after the next ask
    int64_t first_us = 0;    // when first asked, for the round trip
    bool awaited = false;    // waited for (holds()), not yet known to be lost
  };
  struct Stream {
    std::string channel;
    uint64_t next = 0;       // next number to hand on; 0: nothing heard yet
    uint64_t gone_below = 0; // the sender no longer keeps numbers below this
    int64_t handed_utime = 0; // receive time of the last message handed on
    std::map<uint64_t, Held> held;
    std::map<uint64_t, Ask> missing;
  };
  struct Sender {
    int64_t last_heard_us = 0;
    bool dead = false;
    bool leaving = false;  // said it is ending
    std::string process;   // as its state names it
  };
  int64_t silenceAllowed(const Sender& sender) const {
    return sender.leaving ? options_.left_after_us : options_.dead_after_us;
  }
  using Key = std::pair<uint64_t, std::string>;

  Stream& streamOf(uint64_t sender, std::string_view channel);
  void start(Stream& stream, uint64_t first_heard, int64_t stream_start_us, int64_t now_us);
  void markMissing(Stream& stream, uint64_t from, uint64_t to, int64_t now_us);
  void filled(Stream& stream, uint64_t sequence, int64_t now_us);
  void advance(uint64_t sender, Stream& stream, bool sender_dead, const Handler& deliver);
  void hear(uint64_t sender, int64_t now_us);
  const char* silentWhy(uint64_t sender) const;
  void countLost(uint64_t sender, const Stream& stream, uint64_t sequence, const char* why);

  Tracks tracks_;
  Options options_;
  std::map<Key, Stream> streams_;
  std::map<uint64_t, Sender> senders_;
  int64_t round_trip_us_ = 5'000;
  Stats stats_;
  std::vector<std::string> lost_named_;
};

}  // namespace beft::transport::detail
