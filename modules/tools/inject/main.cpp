// beft-inject: plays copies of a run's logged messages onto an LCM URL,
// damaged or as they are, at a fixed rate: the malformed and foreign traffic
// of a shared lab network, for robustness tests and `beft bench faults`.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <random>
#include <thread>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/command_line.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/log_reader.hpp"
#include "tools/inject/message_damage.hpp"
#include "lib/wire/run_identity.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
void onSignal(int) { g_stop = 1; }

struct Options {
  std::string log_path, lcm_url, damage = "all", into_run;
  double rate = 3000, seconds = 0;
  bool as_is = false;
  uint64_t seed = 1;
  std::size_t max_events = 20000;
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Publishes copies of the messages of a recorded run (LOG) on an LCM URL at a fixed rate, damaged "
      "(bit flips, truncation, trailing junk, another type's fingerprint, another channel's message, "
      "overwritten words) or as they are (--as-is: another run on the same URL). Round and round the "
      "log until --seconds have passed or SIGINT/SIGTERM.",
      "beft-inject");
  app.add_option("log", o.log_path, "a run's LCM log")->required()->check(CLI::ExistingFile);
  app.add_option("--lcm-url", o.lcm_url, "where to publish")->required();
  app.add_option("--rate", o.rate, "messages per second")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--seconds", o.seconds, "stop after this long (0: until a signal)")->capture_default_str();
  app.add_option("--damage", o.damage, "bits,truncate,junk,foreign,channel,words | all | malformed")
      ->capture_default_str();
  app.add_flag("--as-is", o.as_is, "no damage: the run's messages, on its channels, as recorded");
  app.add_option("--into-run", o.into_run,
                 "publish on this run's channels (hex id, as channels show it after '@') instead of the log's");
  app.add_option("--seed", o.seed, "seed of the damage")->capture_default_str();
  app.add_option("--max-events", o.max_events, "events of the log kept in memory")->capture_default_str();
  return beft::parseCommandLine(app, argc, argv);
}

// The log's messages (at most --max-events), on the channels of --into-run
// if given. Throws on an unreadable log or a bad run id.
std::vector<beft::inject::DamagedMessage> loggedMessages(const Options& o) {
  int64_t into_run = -1;
  if (!o.into_run.empty()) into_run = beft::wire::parseRunId(o.into_run);
  std::vector<beft::inject::DamagedMessage> events;
  beft::wire::LogReader log(o.log_path);
  beft::wire::LogEvent event;
  while (events.size() < o.max_events && log.next(event)) {
    const auto split = beft::wire::splitRunChannel(event.channel);
    if (beft::wire::isUrlWideChannel(event.channel)) continue;  // another run's beacon would be a lie
    const std::string channel =
        into_run >= 0 ? beft::wire::runChannel(std::string(split.base), into_run) : event.channel;
    events.push_back({channel, event.data});
  }
  return events;
}

// Publishes the events round and round at --rate, each damaged by one of
// `kinds` (or as it is with --as-is), until --seconds or a signal; returns
// how many were sent.
uint64_t publishUntilStopped(lcm::LCM& lcm, const std::vector<beft::inject::DamagedMessage>& events,
                             const std::vector<beft::inject::Damage>& kinds, const Options& o,
                             std::chrono::steady_clock::time_point start) {
  using Clock = std::chrono::steady_clock;
  std::mt19937_64 random(o.seed);
  const auto period = std::chrono::duration<double>(1.0 / o.rate);
  uint64_t sent = 0;
  std::size_t next = 0;
  while (!g_stop && (o.seconds <= 0 || Clock::now() - start < std::chrono::duration<double>(o.seconds))) {
    const auto& original = events[next];
    next = (next + 1) % events.size();
    if (o.as_is) {
      beft::transport::publishEncoded(lcm, original.channel, original.data.data(), original.data.size());
    } else {
      const auto kind = kinds[random() % kinds.size()];
      const auto& other = events[random() % events.size()];
      const auto damaged = beft::inject::damage(original.channel, original.data, kind, other, random);
      beft::transport::publishEncoded(lcm, damaged.channel, damaged.data.data(), damaged.data.size());
    }
    ++sent;
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(period * static_cast<double>(sent)));
  }
  return sent;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  std::vector<beft::inject::Damage> kinds;
  std::vector<beft::inject::DamagedMessage> events;
  try {
    if (!o.as_is) kinds = beft::inject::parseDamage(o.damage);
    events = loggedMessages(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-inject: error: %s\n", e.what());
    return 2;
  }
  if (events.empty()) {
    std::fprintf(stderr, "beft-inject: error: %s holds no message\n", o.log_path.c_str());
    return 2;
  }
  lcm::LCM lcm(o.lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "beft-inject: error: cannot open LCM at %s\n", o.lcm_url.c_str());
    return 1;
  }
  std::unique_ptr<beft::transport::PublisherScope> publishing;
  try {
    publishing = beft::transport::attachPublisher(lcm, o.lcm_url, "beft-inject");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-inject: error: cannot publish on %s: %s\n", o.lcm_url.c_str(), e.what());
    return 1;
  }
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  const auto start = std::chrono::steady_clock::now();
  const uint64_t sent = publishUntilStopped(lcm, events, kinds, o, start);
  std::printf("beft-inject: published %llu messages in %.1f s\n", static_cast<unsigned long long>(sent),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return 0;
}
