// beft-blackboard: keeps the history of everything published on the bus and
// answers late joiners' snapshot queries. Not an expert: it is never fired,
// it runs freely beside the system.
#include <csignal>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>

#include "blackboard/blackboard_service.hpp"
#include "blackboard/message_decoder.hpp"
#include "channels.hpp"
#include "heap_retention.hpp"
#include "lcm_url.hpp"
#include "log.hpp"
#include "transport.hpp"

namespace {

using beft::blackboard::BlackboardService;

volatile std::sig_atomic_t g_stop = 0;
void onSignal(int) { g_stop = 1; }

int64_t wallUtime() {
  using namespace std::chrono;
  return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count();
}

std::string interfaceText(const std::vector<std::string>& exclude) {
  std::string excluded;
  for (const auto& pattern : exclude) excluded += (excluded.empty() ? "" : ", ") + pattern;
  return "process: blackboard\n"
         "reads:\n"
         "  .*  (every channel, any beft type; not " + excluded + ", BB_QUERY, BB_SNAPSHOT_*)\n"
         "  " + std::string(beft::channels::kBlackboardQuery) + "  (beft.bb_query_t)\n"
         "writes:\n"
         "  " + std::string(beft::channels::kBlackboardSnapshotPrefix) +
         "<requester>  (beft.bb_snapshot_t, the answer to a query)\n";
}

class BlackboardProcess {
 public:
  explicit BlackboardProcess(lcm::LCM& lcm, BlackboardService& service) : lcm_(lcm), service_(service) {}

  // Queries by name; everything else is stored (or refused by the service).
  void onMessage(const beft::transport::Message& message) {
    const std::string channel(message.channel);
    if (channel == beft::channels::kBlackboardQuery) {
      beft::bb_query_t query;
      const int size = static_cast<int>(message.size);
      if (query.decode(message.data, 0, size) == size) onQuery(query);
      else beft::log::warn("dropped a ", size, "-byte message on ", channel, " that is not a bb_query_t");
      return;
    }
    onAnyMessage(channel, message.data, static_cast<int>(message.size));
  }

  void onAnyMessage(const std::string& channel, const void* data, int size) {
    try {
      const auto verdict = service_.onMessage(channel, data, size);
      if (verdict == BlackboardService::Verdict::StoredNewChannel) {
        const std::string type = beft::blackboard::typeNameOf(data, size);
        if (type.empty())
          beft::log::warn("new channel ", channel, ": unknown type (fingerprint not of any beft type), stored anyway");
        else
          beft::log::info("new channel ", channel, " (", type, ")");
      } else if (verdict == BlackboardService::Verdict::Rejected) {
        beft::log::warn("dropped a ", size, "-byte message on ", channel,
                        ": too short for a fingerprint and a utime");
      }
    } catch (const std::exception& error) {
      beft::log::error("storing a message on ", channel, " failed: ", error.what());
    }
  }

  void onQuery(const beft::bb_query_t& query_message) {
    const beft::bb_query_t* query = &query_message;
    try {
      const auto start = std::chrono::steady_clock::now();
      std::string why_not;
      auto answer = service_.answer(*query, wallUtime(), &why_not);
      if (!answer) {
        beft::log::warn("ignored a query: ", why_not);
        return;
      }
      const int status = lcm_.publish(answer->channel, &answer->snapshot);
      const double elapsed_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      std::size_t bytes = 0;
      for (const auto& entry : answer->snapshot.entries) bytes += entry.data.size();
      std::string asked = query->channels.empty() ? "all channels" : std::to_string(query->channels.size()) + " asked";
      std::string missing;
      for (const auto& channel : answer->missing) missing += (missing.empty() ? "; nothing on " : ", ") + channel;
      if (status < 0) {
        beft::log::error("could not publish the answer to query ", query->query_id, " on ", answer->channel);
        return;
      }
      char size_text[32];
      std::snprintf(size_text, sizeof size_text, "%.1f kB", static_cast<double>(bytes) / 1e3);
      char time_text[32];
      std::snprintf(time_text, sizeof time_text, "%.2f ms", elapsed_ms);
      beft::log::info("answered query ", query->query_id, " from '", query->requester, "' (", asked, "): ",
                      answer->snapshot.num_entries, " channels, ", size_text, " in ", time_text, missing);
    } catch (const std::exception& error) {
      beft::log::error("answering query ", query->query_id, " from '", query->requester, "' failed: ", error.what());
    }
  }

 private:
  lcm::LCM& lcm_;
  BlackboardService& service_;
};

}  // namespace

int main(int argc, char** argv) {
  beft::retainFreedHeapMemory();
  std::string lcm_url = beft::defaultLcmUrl();
  BlackboardService::Options options;
  double max_channel_mb = static_cast<double>(options.limits.max_channel_bytes) / (1 << 20);
  std::vector<std::string> exclude = options.exclude;
  double status_period = 10.0;
  int queue_capacity = 2000;
  int batch_ms = 10;
  bool show_interface = false;

  CLI::App app(
      "The blackboard: keeps the latest messages of every channel (a bounded history per channel, with "
      "sequence numbers and each message's utime) and answers bb_query_t on BB_QUERY with a bb_snapshot_t "
      "on BB_SNAPSHOT_<requester> holding the latest message of each channel asked for, so a process started "
      "late catches up at once. Not fired by the arbiter: it runs freely. See the content with "
      "'beft blackboard dump'.",
      "beft-blackboard");
  app.add_option("--lcm-url", lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--history", options.limits.history, "messages kept per channel")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--max-channel-mb", max_channel_mb,
                 "memory kept per channel [MiB]; older messages go first, the latest always stays")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--exclude", exclude,
                 "channels not stored: a POSIX extended regular expression matched against the whole name (repeatable; "
                 "replaces the default list). BB_QUERY and BB_SNAPSHOT_* are never stored.")
      ->capture_default_str();
  app.add_option("--status-period", status_period, "seconds between status lines, 0 for none")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  app.add_option("--queue", queue_capacity,
                 "LCM queue capacity of the all-channel subscription, when LCM's own receive thread is used "
                 "(not udpm, or BEFT_UDPM_RECEIVER=0) [messages]")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  app.add_option("--batch-ms", batch_ms,
                 "milliseconds between reads of the stored traffic on udpm (the kernel queues it meanwhile); "
                 "a query is answered at once, after everything sent before it is stored")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  app.add_flag("--interface", show_interface, "print the channels read and written");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  }
  beft::log::setProcessName("blackboard");
  if (show_interface) {
    std::fputs(interfaceText(exclude).c_str(), stdout);
    return 0;
  }
  options.exclude = exclude;
  options.limits.max_channel_bytes = static_cast<std::size_t>(max_channel_mb * (1 << 20));

  std::optional<BlackboardService> service;
  try {
    service.emplace(options);
  } catch (const std::invalid_argument& error) {
    beft::log::error(error.what());
    return 2;
  }
  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    beft::log::error("cannot open LCM at ", lcm_url);
    return 1;
  }

  // Two sources on udpm: the stored traffic on a socket read every
  // --batch-ms (one wake-up for many messages), and BB_QUERY on one that
  // wakes the process at once. Excluded channels named plainly (FIRE, DONE,
  // ...) are dropped in the kernel.
  BlackboardProcess process(lcm, *service);
  beft::transport::Selection stored;
  stored.mode = beft::transport::Selection::Mode::RejectListed;
  for (const auto& pattern : options.exclude)
    if (beft::transport::isPlainChannel(pattern))
      stored.rules.push_back(beft::transport::channelRule(pattern));
  beft::transport::Selection queries;
  queries.rules.push_back(beft::transport::channelRule(beft::channels::kBlackboardQuery));
  std::unique_ptr<beft::transport::Receiver> stored_source, query_source;
  try {
    beft::transport::SplitReceivers sources = beft::transport::openSplitReceivers(lcm, lcm_url, queries, stored, 64, queue_capacity);
    query_source = std::move(sources.wake);
    stored_source = std::move(sources.queued);
  } catch (const std::exception& error) {
    beft::log::error("cannot receive on ", lcm_url, ": ", error.what());
    return 1;
  }
  if (stored_source) {
    beft::log::info("queries: ", query_source->description());
    beft::log::info("stored: ", stored_source->description());
  } else {
    beft::log::info("receiving: ", query_source->description());  // one LCM subscription: queries and the rest
  }
  const beft::transport::Handler handler = [&process](const beft::transport::Message& message) {
    process.onMessage(message);
  };
  const bool gather = stored_source && beft::transport::roomToGather(stored_source->receiveBufferBytes());
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  std::string excluded;
  for (const auto& pattern : options.exclude) excluded += (excluded.empty() ? "" : ", ") + pattern;
  beft::log::info("listening on ", lcm_url, ": keeping ", options.limits.history, " messages per channel (at most ",
                  max_channel_mb, " MiB), not storing ", excluded.empty() ? "nothing" : excluded);

  using Clock = std::chrono::steady_clock;
  auto next_status = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(status_period));
  while (!g_stop) {
    // A query wakes it at once; stored traffic is read at least every batch.
    beft::transport::waitReadable({query_source->fd(), stored_source && !gather ? stored_source->fd() : -1},
                             gather ? batch_ms : 200);
    // Stored traffic first: a query is answered with everything sent before it.
    if ((stored_source && stored_source->drain(handler) < 0) || query_source->drain(handler) < 0) {
      if (g_stop) break;  // a signal interrupted the wait
      beft::log::error("LCM failed while waiting for messages");
      return 1;
    }
    if (status_period > 0 && Clock::now() >= next_status) {
      beft::log::info("status: ", service->statusLine());
      next_status += std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(status_period));
      if (next_status < Clock::now())
        next_status = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(status_period));
    }
  }
  beft::log::info("stopping: ", service->statusLine());
  return 0;
}
