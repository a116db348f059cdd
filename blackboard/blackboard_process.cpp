#include "blackboard/blackboard_process.hpp"

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <utility>

#include <CLI/CLI.hpp>
#include <beft/bb_query_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/wire/message_decoder.hpp"
#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/run_identity.hpp"
#include "lib/transport/transport.hpp"

namespace beft::blackboard {

namespace {

int64_t wallUtime() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

}  // namespace

// Queries answered at once, everything else stored (or refused by the service).
class Traffic {
 public:
  Traffic(lcm::LCM& lcm, BlackboardService& service, const service::AnswerWritePort<beft::bb_snapshot_t>& answers)
      : lcm_(lcm), service_(service), answers_(answers) {}

  void onAnyMessage(const std::string& channel, const void* data, int size) {
    try {
      const auto verdict = service_.onMessage(channel, data, size);
      if (verdict == BlackboardService::Verdict::StoredNewChannel) {
        const std::string type = typeNameOf(data, size);
        if (type.empty())
          log::warn("new channel ", channel, ": unknown type (fingerprint not of any beft type), stored anyway");
        else
          log::info("new channel ", channel, " (", type, ")");
      }
    } catch (const std::exception& error) {
      log::error("storing a message on ", channel, " failed: ", error.what());
    }
  }

  void onQuery(const beft::bb_query_t& query_message) {
    const beft::bb_query_t* query = &query_message;
    try {
      const auto start = std::chrono::steady_clock::now();
      std::string why_not;
      auto answer = service_.answer(*query, wallUtime(), &why_not);
      if (!answer) {
        log::warn("ignored a query: ", why_not);
        return;
      }
      const int status = answers_.publish(lcm_, answer->channel, answer->snapshot);
      const double elapsed_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      std::size_t bytes = 0;
      for (const auto& entry : answer->snapshot.entries) bytes += entry.data.size();
      std::string asked = query->channels.empty() ? "all channels" : std::to_string(query->channels.size()) + " asked";
      std::string missing;
      for (const auto& channel : answer->missing) missing += (missing.empty() ? "; nothing on " : ", ") + channel;
      if (status < 0) {
        log::error("could not publish the answer to query ", query->query_id, " on ", answer->channel);
        return;
      }
      char size_text[32];
      std::snprintf(size_text, sizeof size_text, "%.1f kB", static_cast<double>(bytes) / 1e3);
      char time_text[32];
      std::snprintf(time_text, sizeof time_text, "%.2f ms", elapsed_ms);
      log::info("answered query ", query->query_id, " from '", query->requester, "' (", asked, "): ",
                      answer->snapshot.num_entries, " channels, ", size_text, " in ", time_text, missing);
    } catch (const std::exception& error) {
      log::error("answering query ", query->query_id, " from '", query->requester, "' failed: ", error.what());
    }
  }

 private:
  lcm::LCM& lcm_;
  BlackboardService& service_;
  const service::AnswerWritePort<beft::bb_snapshot_t>& answers_;
};

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

using Clock = std::chrono::steady_clock;
Clock::duration seconds(double s) { return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s)); }

}  // namespace

std::string BlackboardProcess::description() const {
  return "The blackboard: keeps the latest messages of every channel (a bounded history per channel, with "
         "sequence numbers and each message's utime) and answers bb_query_t on BB_QUERY with a bb_snapshot_t "
         "on BB_SNAPSHOT_<requester> holding the latest message of each channel asked for, so a process started "
         "late catches up at once. Not fired by the arbiter: it runs freely. See the content with "
         "'beft blackboard dump'.";
}

void BlackboardProcess::onQuery(const beft::bb_query_t& query) {
  if (traffic_ != nullptr) traffic_->onQuery(query);
}

void BlackboardProcess::store(const transport::Message& message) {
  if (traffic_ != nullptr)
    traffic_->onAnyMessage(std::string(message.channel), message.data, static_cast<int>(message.size));
}

void BlackboardProcess::addOptions(CLI::App& app) {
  app.add_option("--history", options_.limits.history, "messages kept per channel")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--max-channel-mb", max_channel_mb_,
                 "memory kept per channel [MiB]; older messages go first, the latest always stays")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--exclude", options_.exclude,
                 "channels not stored: a POSIX extended regular expression matched against the whole name (repeatable; "
                 "replaces the default list). BB_QUERY and BB_SNAPSHOT_* are never stored.")
      ->capture_default_str();
  app.add_option("--status-period", status_period_, "seconds between status lines, 0 for none")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--queue", queue_capacity_,
                 "LCM queue capacity of the all-channel subscription, when LCM's own receive thread is used "
                 "(not udpm, or BEFT_UDPM_RECEIVER=0) [messages]")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--batch-ms", batch_ms_,
                 "milliseconds between reads of the stored traffic on udpm (the kernel queues it meanwhile); "
                 "a query is answered at once, after everything sent before it is stored")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
}

void BlackboardProcess::onStartUp() {
  options_.limits.max_channel_bytes = static_cast<std::size_t>(max_channel_mb_ * (1 << 20));
}

int BlackboardProcess::serve(service::Context& context) {
  std::optional<BlackboardService> service;
  try {
    service.emplace(options_);
  } catch (const std::invalid_argument& error) {
    log::error(error.what());
    return 2;
  }
  // Two receivers on udpm: the stored traffic on a socket read every
  // --batch-ms (one wake-up for many messages), and BB_QUERY on one that
  // wakes the process at once. Excluded channels named plainly (FIRE, DONE,
  // ...) are dropped in the kernel.
  const transport::Selection stored = selection(service::Delivery::kQueued);
  const transport::Selection queries = selection(service::Delivery::kWakes);
  transport::SplitReceivers sources;
  try {
    sources = transport::openSplitReceivers(context.lcm, context.lcm_url, queries, stored, 64, queue_capacity_);
  } catch (const std::exception& error) {
    log::error("cannot receive on ", context.lcm_url, ": ", error.what());
    return 1;
  }
  if (sources.queued) {
    log::info("queries: ", sources.wake->description());
    log::info("stored: ", sources.queued->description());
  } else {
    log::info("receiving: ", sources.wake->description());  // one LCM subscription: queries and the rest
  }
  Traffic traffic(context.lcm, *service, answers_out_);
  traffic_ = &traffic;  // until serve() returns
  const std::unique_ptr<Traffic*, void (*)(Traffic**)> serving(&traffic_, [](Traffic** slot) { *slot = nullptr; });
  const transport::Handler handler = [this](const transport::Message& message) { dispatch(message); };
  if (!context.resume_log.empty()) {
    // After a crash: the history it held, from the run's log (queries in it are not answered again).
    try {
      wire::LogReader log(context.resume_log);
      wire::LogEvent event;
      while (log.nextOfRun(event, wire::runId())) service->onMessage(event.channel, event.data.data(), static_cast<int>(event.data.size()));
      log::info("resumed from ", context.resume_log, ": ", service->statusLine());
    } catch (const std::exception& e) {
      log::error("cannot resume from ", context.resume_log, ": ", e.what());
      return 1;
    }
  }
  const bool gather = sources.queued && transport::roomToGather(sources.queued->receiveBufferBytes());
  const std::string excluded = joined(options_.exclude);
  log::info("listening on ", context.lcm_url, ": keeping ", options_.limits.history, " messages per channel (at most ",
            max_channel_mb_, " MiB), not storing ", excluded.empty() ? "nothing" : excluded);
  auto next_status = Clock::now() + seconds(status_period_);
  // Heartbeats once it listens: the arbiter waits for the first (mission.xml:
  // --wait-for blackboard), or a message sent before, such as the ground
  // truth that goes out only when the scene changes, would never be held.
  service::HeartbeatSender heartbeats(context.lcm, heartbeat_out_, context.process_name);
  while (!context.stop.any()) {
    heartbeats.update(std::exchange(arbiter_waiting_, false));
    // A query wakes it at once; stored traffic is read at least every batch.
    transport::waitReadable({sources.wake->fd(), sources.queued && !gather ? sources.queued->fd() : -1},
                            gather ? batch_ms_ : 200);
    // Stored traffic around the queries: a query is answered with everything sent before it.
    if (transport::drainSplit(*sources.wake, sources.queued.get(), handler) < 0) {
      if (context.stop.any()) break;  // a signal interrupted the wait
      log::error("LCM failed while waiting for messages");
      return 1;
    }
    if (status_period_ > 0 && Clock::now() >= next_status) {
      log::info("status: ", service->statusLine());
      next_status += seconds(status_period_);
      if (next_status < Clock::now()) next_status = Clock::now() + seconds(status_period_);
    }
  }
  log::info("stopping: ", service->statusLine());
  return 0;
}

}  // namespace beft::blackboard
