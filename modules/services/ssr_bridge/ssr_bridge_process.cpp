#include "services/ssr_bridge/ssr_bridge_process.hpp"

#include <poll.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include <CLI/CLI.hpp>
#include "lib/common/channels.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/blackboard_query.hpp"

namespace beft::ssr_bridge {

std::string SsrBridgeProcess::description() const {
  return "beft-ssr-bridge: mirrors a run into a running SoundScape Renderer (SSR, e.g. ssr-binaural "
         "--ip-server) over its XML network interface, so a person hears the scene from the robot's ears: one SSR "
         "source per sound of an acoustic object (SSR opens the WAV file itself: give --scenario so that the "
         "scenario's relative sound paths resolve), moved as the object moves, muted while it does not sound, its "
         "volume from the object's level; SSR's listener at the robot's head, looking where the head looks. It "
         "clears SSR's scene when it connects, sends only what changed, only listens to the run (nothing waits "
         "for it), and tries again every second while SSR is not there.";
}

void SsrBridgeProcess::addOptions(CLI::App& app) {
  app.add_option("--ssr-host", ssr_host_, "host of SSR's network interface")->capture_default_str();
  app.add_option("--ssr-port", ssr_port_, "port of SSR's network interface (ssr-binaural --ip-server=PORT)")
      ->capture_default_str()
      ->check(CLI::Range(1, 65535));
  app.add_option("--scenario", scenario_,
                 "the run's scenario file: its sound paths are relative to it (default: to the current directory)");
  app.add_option("--batch-ms", batch_ms_,
                 "milliseconds to let the run's messages gather between reads; SSR is told at most that often "
                 "(and at most once a tick)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
}

void SsrBridgeProcess::onStartUp() {
  if (!scenario_.empty() && !std::filesystem::is_regular_file(scenario_))
    throw std::invalid_argument("--scenario " + scenario_ + ": no such file");
}

void SsrBridgeProcess::keepObjects(const uint8_t* data, std::size_t size) {
  newest_objects_.assign(data, data + size);
  heard_objects_ = true;
  heard_news_ = true;
}

void SsrBridgeProcess::onSceneAnswer(const beft::bb_snapshot_t& snapshot) {
  if (heard_objects_) return;
  for (const auto& entry : snapshot.entries)
    if (entry.channel == channels::kGroundTruth.name && !entry.data.empty()) {
      keepObjects(entry.data.data(), entry.data.size());
      log::info("the scene in force from the blackboard (its ground truth of t = ", entry.utime * 1e-6, " s)");
    }
}

void SsrBridgeProcess::tellSsr(SsrLink& link, SceneMirror& mirror) {
  if (!newest_objects_.empty()) {
    beft::scene_objects_t objects{};
    if (objects_in_.decode(newest_objects_, objects))
      mirror.setObjects(objects);
    newest_objects_.clear();
  }
  if (!newest_robot_.empty()) {
    beft::robot_state_t robot{};
    if (robot_in_.decode(newest_robot_, robot))
      mirror.setRobot(robot);
    newest_robot_.clear();
  }
  heard_news_ = false;
  for (const auto& request : mirror.requests()) link.send(request);
  logWarnings(mirror);
}

void SsrBridgeProcess::readSsr(const std::vector<std::string>& messages, SceneMirror& mirror) {
  for (const auto& message : messages) {
    // Names reported before SSR's state ended are those of an earlier scene, which the bridge clears.
    const bool checking = ssr_scene_.state_received;
    UpdateNews news;
    if (!applyUpdate(message, ssr_scene_, &news)) {
      if (unreadable_++ == 0)
        log::warn("a message from SSR is not an update this bridge can read (more are counted): ",
                  message.substr(0, 200));
      continue;
    }
    if (!checking) continue;
    for (const auto& [number, name] : news.names)
      if (const std::string warning = mirror.sourceNamed(number, name); !warning.empty()) log::warn(warning);
  }
}

void SsrBridgeProcess::askForTheScene(lcm::LCM& lcm) {
  const auto now = std::chrono::steady_clock::now();
  if (heard_objects_ || now < next_query_) return;
  next_query_ = now + std::chrono::milliseconds(200);
  query_out_.publish(lcm, wire::blackboardQuery(scene_answer_in_.channel(), ++queries_, {channels::kGroundTruth.name}));
}

void SsrBridgeProcess::logWarnings(SceneMirror& mirror) {
  for (const auto& warning : mirror.takeWarnings()) log::warn(warning);
}

int SsrBridgeProcess::serve(service::Context& context) {
  scene_answer_in_.answerOn(wire::blackboardAnswerChannel(context.process_name));
  std::unique_ptr<transport::Receiver> receiver;
  try {
    receiver = transport::openReceiver(context.lcm, context.lcm_url, selection(service::Delivery::kWakes));
  } catch (const std::exception& e) {
    log::error("cannot receive on ", context.lcm_url, ": ", e.what());
    return 1;
  }
  log::info("receiving: ", receiver->description());
  const std::string scenario_dir =
      scenario_.empty() ? "" : std::filesystem::absolute(scenario_).parent_path().string();
  SceneMirror mirror(scenario_dir);
  SsrLink link(ssr_host_, ssr_port_);
  log::info("mirroring the run into SSR at ", link.address(),
            scenario_.empty() ? ", sounds relative to the current directory" : ", sounds relative to " + scenario_dir);
  const transport::Handler keep = [this](const transport::Message& m) { dispatch(m); };
  std::vector<std::string> from_ssr;
  while (!context.stop.any()) {
    askForTheScene(context.lcm);
    pollfd fds[2] = {{receiver->fd(), POLLIN, 0}, {link.fd(), link.events(), 0}};
    const int until_attempt = link.millisecondsUntilAttempt();
    poll(fds, link.fd() >= 0 ? 2 : 1, until_attempt < 0 ? 100 : std::min(until_attempt, 100));
    if (receiver->drain(keep) < 0 && !context.stop.any()) {
      log::error("LCM receive failed");
      return 1;
    }
    from_ssr.clear();
    const SsrLink::Event event = link.service(from_ssr);
    if (event == SsrLink::Event::Connected) {
      ssr_scene_ = SsrScene{};
      mirror.restart();
    }
    readSsr(from_ssr, mirror);
    if (link.connected() && (heard_news_ || event == SsrLink::Event::Connected)) {
      tellSsr(link, mirror);
      // Let the run's next messages gather: SSR needs no more than a few updates per second of wall time.
      if (batch_ms_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(batch_ms_));
    }
  }
  // What the run said last, so that SSR ends where the run ended. A bridge
  // that started late (it runs at background priority) may not have the
  // scene yet: the blackboard, still up while listeners stop, is asked once more.
  receiver->drain(keep);
  if (!heard_objects_ && link.connected()) {
    next_query_ = std::chrono::steady_clock::now();
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    while (!heard_objects_ && std::chrono::steady_clock::now() < give_up) {
      askForTheScene(context.lcm);
      pollfd fd{receiver->fd(), POLLIN, 0};
      poll(&fd, 1, 50);
      receiver->drain(keep);
    }
    if (!heard_objects_) log::warn("no scene heard from the run or the blackboard: SSR shows none");
  }
  if (link.connected()) {
    tellSsr(link, mirror);
    if (!link.flush(std::chrono::milliseconds(1000))) log::warn("SSR did not take the last requests within 1 s");
  }
  if (unreadable_ > 0) log::info(unreadable_, " message(s) from SSR could not be read");
  log::info("stopping; ", mirror.sourceCount(), " sound(s) mirrored");
  return 0;
}

}  // namespace beft::ssr_bridge
