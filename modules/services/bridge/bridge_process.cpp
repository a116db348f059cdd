#include "services/bridge/bridge_process.hpp"

#include <malloc.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <CLI/CLI.hpp>

#include "lib/common/clocks.hpp"
#include "lib/common/log.hpp"
#include "lib/expert/frontier.hpp"
#include "lib/task/task_commands.hpp"
#include "lib/task/task_stack.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/run_discovery.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_identity.hpp"
#include "services/bridge/gathered_reads.hpp"
#include "services/bridge/net_drawing.hpp"
#include "services/bridge/web_server.hpp"

#ifndef BEFT_WEB_DIR
#define BEFT_WEB_DIR "share/beft/web"
#endif

namespace beft::bridge {

namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kTimerPeriod = std::chrono::milliseconds(50);

}  // namespace

BridgeProcess::BridgeProcess() { options_.web_dir = BEFT_WEB_DIR; }
BridgeProcess::~BridgeProcess() = default;

std::string BridgeProcess::description() const {
  return "beft-bridge: shows a run, or a run's log (--log), to web viewers over the Foxglove WebSocket protocol "
         "(foxglove.websocket.v1: Foxglove, or the page it serves over plain HTTP on the same port, from --web-dir). "
         "Every channel of the run is a topic (its name without the run id, JSON with its JSON Schema); /scene, "
         "/tf, /obstacle_map, /camera/color, /camera/depth and /log come in Foxglove's own schemas. A viewer may "
         "publish (clientPublish, encoding json) on /beft/run_control {\"action\":\"pause\"|\"run\"|\"step\"}, "
         "/beft/task {\"action\":\"goto\",\"x\":X,\"y\":Y[,\"yaw\":DEG]} | {\"action\":\"look_at\",\"object_id\":ID} "
         "| {\"action\":\"clear\"}, and, playing a log, /beft/playback {\"action\":\"play\"[,\"speed\":S]} | "
         "pause | step | {\"action\":\"seek\",\"time_ns\":T}. Controls from another host than this one need "
         "--token, given as ws://HOST:PORT/?token=TOKEN. The run never waits for the bridge; a viewer that reads "
         "slowly loses frames, not the run.";
}

void BridgeProcess::addOptions(CLI::App& app) {
  app.add_option("--port", options_.port, "TCP port of the page and the WebSocket (0: any free one)")
      ->capture_default_str()
      ->check(CLI::Range(0, 65535));
  app.add_option("--bind", options_.bind, "address to listen on (0.0.0.0: every interface)")->capture_default_str();
  app.add_option("--web-dir", options_.web_dir, "the viewer page's files")->capture_default_str();
  app.add_option("--token", options_.token,
                 "what a viewer on another host must give (?token=... in the WebSocket URL) to send controls");
  app.add_option("--log", options_.log, "play this run's log instead of a live run");
  app.add_option("--speed", options_.speed, "playing a log: log seconds per second")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1000.0));
  app.add_flag("--paused", options_.paused, "playing a log: start paused");
  app.add_option("--log-file", options_.log_file, "the processes' log to show on /log as it grows (\"\": none)");
  app.add_option("--run-id", options_.run_id, "the run to show (hex; default: BEFT_RUN_ID, else the one heard)");
  app.add_option("--scenario", options_.scenario, "the run's scenario, named to viewers");
  app.add_option("--net", options_.net,
                 "the run's Petri net (PNML): drawn by Graphviz for the page (/net.svg), which lights its marking");
  app.add_option("--batch-ms", options_.batch_ms,
                 "live: milliseconds to let the run's messages gather between reads (one wake-up for many; the "
                 "kernel queues them meanwhile); 0 reads each as it comes")
      ->capture_default_str()
      ->check(CLI::Range(0, 50));
  app.add_option("--max-clients", options_.max_clients, "WebSocket clients at once")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
}

void BridgeProcess::onStartUp() {
  // Unlike a process that builds the same buffers every firing (lib/common/heap_retention.hpp), the bridge
  // makes large short-lived frames at the pace of the run's data: glibc's defaults hand them back, so its
  // memory follows what it holds now instead of staying at its peak.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  mallopt(M_TRIM_THRESHOLD, 128 * 1024);
  mallopt(M_TOP_PAD, 0);
  if (!options_.run_id.empty()) wire::setRunId(wire::parseRunId(options_.run_id));
  if (!options_.log.empty() && !std::filesystem::is_regular_file(options_.log))
    throw std::invalid_argument("--log " + options_.log + ": no such file");
  if (!std::filesystem::is_directory(options_.web_dir))
    log::warn("--web-dir ", options_.web_dir, " is no directory: the page is not served, the WebSocket is");
  if (!options_.log_file.empty()) tail_ = std::make_unique<LogTail>(options_.log_file);
  if (!options_.net.empty()) {
    std::string why;
    net_svg_ = drawNetAsSvg(options_.net, why);
    if (net_svg_.empty()) log::warn("--net ", options_.net, ": not drawn (", why, "); the page lists the marking");
  }
}

HubOptions BridgeProcess::hubOptions(bool log_mode) const {
  HubOptions hub;
  const int64_t started_ms = wallMicros() / 1000;
  const std::string run = log_mode ? wire::runIdText(index_->run_id) : wire::runIdText(wire::runId());
  hub.session_id = run + "-" + std::to_string(started_ms);
  hub.metadata["run"] = run;
  hub.metadata["mode"] = log_mode ? "log" : "live";
  if (!options_.scenario.empty()) hub.metadata["scenario"] = options_.scenario;
  if (log_mode) {
    hub.metadata["log"] = options_.log;
    hub.metadata["start_ns"] = std::to_string(index_->start_utime * 1000);
    hub.metadata["end_ns"] = std::to_string(index_->end_utime * 1000);
  }
  if (!net_svg_.empty()) hub.metadata["net"] = kNetDrawingPath;
  hub.time_capability = log_mode;
  return hub;
}

void BridgeProcess::onRunMessage(const transport::Message& message) {
  const std::string channel(message.channel);
  if (channel == channels::kRunControlState) {
    beft::run_control_t state{};
    if (wire::decodeFrom(channel, message.data, message.size, state)) {
      run_control_.onState(state);
      const bool news = !last_state_told_ || last_state_told_->mode != state.mode ||
                        last_state_told_->sequence != state.sequence || last_state_told_->origin != state.origin;
      if (news) hub_->broadcastStatus(0, "the run: " + service::describeRunControlState(state), "beft.run_control");
      last_state_told_ = state;
    }
  }
  hub_->onRunMessage(channel, message.data, message.size, static_cast<uint64_t>(message.recv_utime) * 1000);
}

int BridgeProcess::serve(service::Context& context) {
  lcm_ = &context.lcm;
  boost::asio::io_context io;
  try {
    return options_.log.empty() ? serveLive(context, io) : serveLog(context, io);
  } catch (const std::exception& e) {  // cannot listen, cannot receive, a log that cannot be read
    log::error(e.what());
    return 1;
  }
}

namespace {

WebServerOptions webOptions(const BridgeOptions& o, const std::string& net_svg) {
  WebServerOptions web;
  if (!net_svg.empty()) web.documents[kNetDrawingPath] = {"image/svg+xml", net_svg};
  web.bind_address = o.bind;
  web.port = o.port;
  web.web_dir = o.web_dir;
  web.token = o.token;
  web.max_clients = static_cast<std::size_t>(o.max_clients);
  return web;
}

}  // namespace

int BridgeProcess::serveLive(service::Context& context, boost::asio::io_context& io) {
  if (wire::runId() == 0) {
    const std::string why = wire::adoptTheRunHeard(context.lcm, 2.0);
    if (!why.empty()) {
      log::error(why);
      return 2;
    }
  }
  hub_ = std::make_unique<FoxgloveHub>(hubOptions(false), *this);
  experts_ = std::make_unique<ExternalExperts>(*this);
  hub_->acceptExperts(*experts_);
  auto receiver = transport::openReceiver(context.lcm, context.lcm_url, selection(service::Delivery::kWakes), 64);
  WebServer server(io, webOptions(options_, net_svg_), *hub_);
  hub_->attach(server);
  log::info("view: http://", options_.bind, ":", server.port(), "/ (", wire::describeRun(wire::runId()), "; ",
            receiver->description(), ")");
  // Read in batches (gathered_reads.hpp): the bridge watches, and woken for
  // each of the run's messages (a few thousand a second at full speed) it
  // would take a CPU from the lockstep chain as often.
  const bool gather = options_.batch_ms > 0 && transport::roomToGather(receiver->receiveBufferBytes());
  const int batch_ms = gather ? options_.batch_ms : 0;
  GatheredReads reads(io, *receiver, [this](const transport::Message& m) { dispatch(m); }, batch_ms,
                      [this] { return !experts_->any(); });
  reads.start();
  runLoop(context, io);
  const transport::RepairStats repair = receiver->repairStats();
  log::info("stopping; ", reads.wakeUps(), " read(s) of the run (", batch_ms, " ms gathering); ",
            hub_->framesDropped(), " frame(s) not sent to slow viewers; receiving: ", repair.gaps,
            " message(s) missed, ", repair.repaired, " repaired, ", repair.lost, " lost, ",
            receiver->kernelDropped(), " datagram(s) dropped by the kernel");
  return 0;
}

int BridgeProcess::serveLog(service::Context& context, boost::asio::io_context& io) {
  const auto started = Clock::now();
  index_ = std::make_unique<LogIndex>(buildLogIndex(options_.log));
  log::info("indexed ", options_.log, " in ", std::chrono::duration<double>(Clock::now() - started).count(), " s: ",
            index_->events, " events over ", (index_->end_utime - index_->start_utime) * 1e-6, " s of ",
            wire::describeRun(index_->run_id), index_->damage.empty() ? "" : "; " + index_->damage);
  hub_ = std::make_unique<FoxgloveHub>(hubOptions(true), *this);
  player_ = std::make_unique<LogPlayer>(*index_, [this](const wire::LogEvent& e) {
    hub_->onRunMessage(e.channel, e.data.data(), e.data.size(), static_cast<uint64_t>(e.timestamp) * 1000);
  });
  WebServer server(io, webOptions(options_, net_svg_), *hub_);
  hub_->attach(server);
  log::info("view: http://", options_.bind, ":", server.port(), "/ (playing ", options_.log, ")");
  if (!options_.paused) player_->play(options_.speed);
  runLoop(context, io);
  return 0;
}

void BridgeProcess::runLoop(service::Context& context, boost::asio::io_context& io) {
  boost::asio::steady_timer timer(io);
  std::function<void()> schedule = [&] {
    timer.expires_after(kTimerPeriod);
    timer.async_wait([&](const boost::system::error_code& e) {
      if (e) return;
      if (context.stop.any()) return io.stop();
      onTimer(context);
      schedule();
    });
  };
  schedule();
  io.run();
}

void BridgeProcess::onTimer(service::Context& context) {
  const auto now = Clock::now();
  if (player_) advancePlayback();
  if (!player_)
    if (auto request = run_control_.due(wallMicros())) control_out_.publish(context.lcm, *request);
  if (tail_ && now >= next_tail_) {
    next_tail_ = now + std::chrono::milliseconds(250);
    const auto lines = tail_->newLines();
    if (!lines.empty()) hub_->publishLogLines(lines, static_cast<uint64_t>(wallMicros()) * 1000);
  }
  hub_->publishDerived();
  hub_->sendThrottled();
  if (now >= next_drop_report_) {
    next_drop_report_ = now + std::chrono::seconds(1);
    hub_->reportDrops();
    if (player_) last_time_sent_ = -1;  // the time again, for viewers that came while paused
  }
  hub_->flush();
}

void BridgeProcess::advancePlayback() {
  player_->advance();
  if (player_->time() != last_time_sent_) {
    last_time_sent_ = player_->time();
    hub_->sendTime(static_cast<uint64_t>(last_time_sent_) * 1000);
  }
  if (player_->atEnd() && !player_->playing() && !told_end_) {
    hub_->broadcastStatus(0, "the end of the log", "beft.playback");
    told_end_ = true;
  }
}

std::string BridgeProcess::runControl(const RunControlRequest& request) {
  if (player_) return std::string(kRunControlTopic) + ": this bridge plays a log: use " + kPlaybackTopic;
  switch (request.action) {
    case RunControlRequest::Action::kRun: run_control_.request(beft::run_control_t::MODE_RUN, 0); break;
    case RunControlRequest::Action::kPause: run_control_.request(beft::run_control_t::MODE_PAUSE, 0); break;
    case RunControlRequest::Action::kStep: run_control_.stepOne(); break;
  }
  return "";
}

std::string BridgeProcess::task(const TaskRequest& request) {
  if (player_) return std::string(kTaskTopic) + ": this bridge plays a log, which takes no tasks";
  const int64_t now = wallMicros();
  beft::task_command_t command{};
  if (request.action == TaskRequest::Action::kClear) {
    command = tasks::clearCommand("viewer", now, now);
  } else {
    tasks::Task task;
    task.kind = request.action == TaskRequest::Action::kGoto ? tasks::kinds::kGoto : tasks::kinds::kLookAt;
    task.x = request.action == TaskRequest::Action::kGoto ? request.x : NAN;
    task.y = request.action == TaskRequest::Action::kGoto ? request.y : NAN;
    task.yaw = request.yaw_deg.value_or(NAN);
    task.object_id = request.object_id;
    task.priority = 50;  // as beft task push: above exploration, below the reflexes
    task.origin = "viewer";
    task.note = "asked in the viewer";
    const std::string error = tasks::validateTask(task);
    if (!error.empty()) return std::string(kTaskTopic) + ": " + error;
    command = tasks::pushCommand(task, now, now);
  }
  if (tasks_out_.publish(*lcm_, command) != 0) return std::string(kTaskTopic) + ": could not publish TASK_COMMAND";
  return "";
}

std::string BridgeProcess::playback(const PlaybackRequest& request) {
  if (!player_) return std::string(kPlaybackTopic) + ": a live run has no playback: use " + kRunControlTopic;
  switch (request.action) {
    case PlaybackRequest::Action::kPlay: player_->play(request.speed.value_or(player_->speed())); break;
    case PlaybackRequest::Action::kPause: player_->pause(); break;
    case PlaybackRequest::Action::kStep: player_->step(); break;
    case PlaybackRequest::Action::kSeek:
      hub_->forgetKept();
      player_->seek(*request.time_ns / 1000);
      break;
  }
  told_end_ = false;
  last_time_sent_ = -1;
  advancePlayback();
  return "";
}

}  // namespace beft::bridge

namespace beft::bridge {

std::string BridgeProcess::publish(const std::string& channel, const std::vector<uint8_t>& bytes) {
  if (lcm_ == nullptr) return "not live";
  return transport::publishEncoded(*lcm_, wire::runChannel(channel), bytes.data(), bytes.size()) == 0
             ? std::string()
             : "could not publish";
}

void BridgeProcess::listPublished(beft::done_t& done) {
  if (lcm_ != nullptr) expert::listPublished(*lcm_, done);
}

}  // namespace beft::bridge
