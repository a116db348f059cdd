// A run's log played back in log time: at a speed, paused, one tick at a
// time, or from any time (seek reads from the index's offset, so every
// channel's latest message before that time, a keyframe and its changes
// included, reaches the sink before playing on).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "services/bridge/log_index.hpp"
#include "lib/wire/log_reader.hpp"

namespace beft::bridge {

class LogPlayer {
 public:
  using Clock = std::chrono::steady_clock;
  // Each event of the run, under its plain channel name, in log order.
  using Sink = std::function<void(const wire::LogEvent& event)>;

  // Starts paused at the log's first event, which it delivers.
  LogPlayer(const LogIndex& index, Sink sink);

  void play(double speed, Clock::time_point now = Clock::now());  // speed > 0
  void pause(Clock::time_point now = Clock::now());
  // On to the next tick: everything up to the tick after the next one (the
  // next tick's robot state and what the experts made of it), then paused.
  void step();
  // To `utime` (clamped to the log), keeping play or pause.
  void seek(int64_t utime, Clock::time_point now = Clock::now());
  // Delivers what log time has reached by `now` (at most `max_events`: the
  // rest on the next call). True if log time moved.
  bool advance(Clock::time_point now = Clock::now(), std::size_t max_events = 2000);

  int64_t time() const { return time_; }  // the log time reached [us]
  bool playing() const { return playing_; }
  double speed() const { return speed_; }
  bool atEnd() const { return at_end_; }
  const LogIndex& index() const { return index_; }
  // The channel whose messages mark ticks (ROBOT_STATE, else RUN_STATUS).
  const std::string& tickChannel() const { return tick_channel_; }

 private:
  bool peek();  // reads the next event into pending_ unless there is one; false at the end
  void deliverPending();
  int64_t clockTime(Clock::time_point now) const;

  const LogIndex& index_;
  Sink sink_;
  std::unique_ptr<wire::LogReader> reader_;
  std::optional<wire::LogEvent> pending_;
  std::string tick_channel_;
  int64_t time_ = 0;
  bool playing_ = false, at_end_ = false;
  double speed_ = 1.0;
  int64_t anchor_time_ = 0;            // log time at anchor_wall_
  Clock::time_point anchor_wall_{};
};

}  // namespace beft::bridge
