#include "services/bridge/log_player.hpp"

#include <algorithm>
#include <map>

#include "lib/common/channels.hpp"

namespace beft::bridge {

LogPlayer::LogPlayer(const LogIndex& index, Sink sink) : index_(index), sink_(std::move(sink)) {
  tick_channel_ = index.channels.count(channels::kRobotState.name) ? channels::kRobotState.name
                                                                   : channels::kRunStatus.name;
  reader_ = std::make_unique<wire::LogReader>(index.path);
  time_ = index.start_utime;
  if (peek() && pending_->timestamp <= time_) deliverPending();
}

bool LogPlayer::peek() {
  if (pending_) return true;
  wire::LogEvent event;
  if (!reader_->nextOfRun(event, index_.run_id)) {
    at_end_ = true;
    return false;
  }
  pending_ = std::move(event);
  return true;
}

void LogPlayer::deliverPending() {
  sink_(*pending_);
  pending_.reset();
}

int64_t LogPlayer::clockTime(Clock::time_point now) const {
  const double elapsed_us = std::chrono::duration<double, std::micro>(now - anchor_wall_).count();
  return anchor_time_ + static_cast<int64_t>(elapsed_us * speed_);
}

void LogPlayer::play(double speed, Clock::time_point now) {
  speed_ = speed > 0 ? speed : 1.0;
  playing_ = true;
  anchor_time_ = time_;
  anchor_wall_ = now;
}

void LogPlayer::pause(Clock::time_point now) {
  if (playing_) advance(now);
  playing_ = false;
}

bool LogPlayer::advance(Clock::time_point now, std::size_t max_events) {
  if (!playing_) return false;
  const int64_t target = std::min(clockTime(now), index_.end_utime);
  const int64_t before = time_;
  std::size_t delivered = 0;
  while (delivered < max_events && peek() && pending_->timestamp <= target) {
    time_ = std::max(time_, pending_->timestamp);
    deliverPending();
    ++delivered;
  }
  if (delivered < max_events) time_ = std::max(time_, target);
  else {  // behind: the clock goes on from where delivery got to
    anchor_time_ = time_;
    anchor_wall_ = now;
  }
  if (!peek()) {
    time_ = index_.end_utime;
    playing_ = false;
  }
  return time_ != before;
}

void LogPlayer::step() {
  playing_ = false;
  int ticks = 0;
  for (std::size_t guard = 0; guard < 1000000 && peek(); ++guard) {
    if (pending_->channel == tick_channel_ && ++ticks == 2) return;
    time_ = std::max(time_, pending_->timestamp);
    deliverPending();
  }
}

void LogPlayer::seek(int64_t utime, Clock::time_point now) {
  utime = std::clamp(utime, index_.start_utime, index_.end_utime);
  reader_ = std::make_unique<wire::LogReader>(index_.path, index_.offsetToRebuild(utime));
  pending_.reset();
  at_end_ = false;
  // Every channel's latest message up to `utime`, delivered in log order.
  std::map<std::string, wire::LogEvent> latest;
  while (peek() && pending_->timestamp <= utime) {
    latest[pending_->channel] = std::move(*pending_);
    pending_.reset();
  }
  std::vector<wire::LogEvent*> ordered;
  for (auto& [channel, event] : latest) ordered.push_back(&event);
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const wire::LogEvent* a, const wire::LogEvent* b) { return a->timestamp < b->timestamp; });
  for (const auto* event : ordered) sink_(*event);
  time_ = utime;
  anchor_time_ = utime;
  anchor_wall_ = now;
}

}  // namespace beft::bridge
