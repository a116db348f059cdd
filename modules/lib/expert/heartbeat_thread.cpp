#include "lib/expert/heartbeat_thread.hpp"

#include <unistd.h>

#include <beft/heartbeat_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::expert {

namespace {

std::string hostName() {
  char buffer[256] = {0};
  if (gethostname(buffer, sizeof(buffer) - 1) != 0) return "unknown";
  return buffer;
}

int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

HeartbeatThread::HeartbeatThread(lcm::LCM& lcm, std::string process_name, double period_s)
    : lcm_(lcm),
      process_name_(std::move(process_name)),
      host_(hostName()),
      period_(std::chrono::microseconds(static_cast<int64_t>(period_s * 1e6))) {
  send();
  thread_ = std::thread([this] { loop(); });
}

HeartbeatThread::~HeartbeatThread() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void HeartbeatThread::setState(bool firing, int64_t last_firing_id) {
  firing_ = firing;
  last_firing_id_ = last_firing_id;
}

void HeartbeatThread::sendNow() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    send_now_ = true;
  }
  wake_.notify_all();
}

void HeartbeatThread::loop() {
  std::unique_lock<std::mutex> lock(mutex_);
  auto next = std::chrono::steady_clock::now() + period_;
  while (!stop_) {
    wake_.wait_until(lock, next, [this] { return stop_ || send_now_; });
    if (stop_) break;
    const bool periodic = std::chrono::steady_clock::now() >= next;
    if (!periodic && !send_now_) continue;
    send_now_ = false;
    lock.unlock();
    send();  // LCM publishes are thread-safe; not under our lock
    lock.lock();
    if (periodic) next = std::chrono::steady_clock::now() + period_;
  }
}

void HeartbeatThread::send() {
  beft::heartbeat_t beat{};
  beat.utime = wallMicros();
  beat.process = process_name_;
  beat.pid = static_cast<int32_t>(getpid());
  beat.host = host_;
  beat.last_firing_id = last_firing_id_.load();
  beat.state = !firing_.load() ? "idle" : waiting_.load() ? "waiting" : "firing";
  transport::publish(lcm_, wire::runChannel(channels::kHeartbeat), beat);
  ++sent_;
}

}  // namespace beft::expert
