#include "lib/service/service.hpp"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/heap_retention.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/common/log.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/reject_report.hpp"
#include "lib/wire/run_identity.hpp"

namespace beft::service {

namespace {

StopSignals g_stop;
void onInterrupt(int) { g_stop.interrupts.fetch_add(1); }
void onTerminate(int) { g_stop.terminated.store(true); }

void listPorts(std::ostream& out, const std::vector<Port>& ports) {
  for (const auto& p : ports)
    out << "  " << p.channel << "  (" << p.type << (p.note.empty() ? "" : ", " + p.note) << ")\n";
}

std::string hostName() {
  char name[256] = {0};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

std::string interfaceText(const Service& service, const std::string& process_name) {
  std::ostringstream out;
  out << "process: " << process_name << "\nreads:\n";
  listPorts(out, service.reads());
  out << "writes:\n";
  listPorts(out, service.writes());
  return out.str();
}

int runServiceMain(int argc, char** argv, Service& service) {
  retainFreedHeapMemory();
  std::string lcm_url = defaultLcmUrl();
  std::string process_name = service.name();
  bool show_interface = false;
  std::string resume_log;
  std::string program = "beft-" + service.name();
  std::replace(program.begin(), program.end(), '_', '-');  // the program's name: dashes for underscores
  CLI::App app(service.description(), program);
  app.add_option("--lcm-url", lcm_url, "LCM URL (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--name", process_name, "process name in logs and heartbeats")->capture_default_str();
  app.add_flag("--interface", show_interface, "print the channels read and written");
  if (service.resumable())
    app.add_option("--resume-log", resume_log,
                   "restarted after a crash: rebuild what this process held from the run's LCM log before "
                   "serving; the launcher passes it");
  service.addOptions(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  log::setProcessName(process_name);
  if (show_interface) {
    std::fputs(interfaceText(service, process_name).c_str(), stdout);
    return 0;
  }
  try {
    service.onStartUp();
  } catch (const std::exception& e) {
    log::error(e.what());
    return 2;
  }
  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    log::error("cannot open LCM at ", lcm_url);
    return 1;
  }
  std::unique_ptr<transport::PublisherScope> publishing;
  try {
    publishing = transport::attachPublisher(lcm, lcm_url, process_name);
  } catch (const std::exception& e) {
    log::error("cannot publish on ", lcm_url, ": ", e.what());
    return 1;
  }
  if (service.belongsToARun()) wire::logRunOf(lcm_url);
  // What this process refuses, told to the run: the report counts it (a log keeps no tags).
  wire::RejectReporter rejects(process_name, [&lcm](const beft::process_rejects_t& account) {
    transport::publish(lcm, wire::runChannel(channels::kProcessRejects), account);
  });
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onTerminate);
  Context context{lcm, lcm_url, process_name, g_stop, resume_log};
  return service.serve(context);
}

HeartbeatSender::HeartbeatSender(lcm::LCM& lcm, const WritePort<beft::heartbeat_t>& port,
                                 const std::string& process_name, double period_s)
    : lcm_(lcm),
      port_(port),
      period_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s))),
      next_(Clock::now()),
      last_waiting_answer_(next_ - std::chrono::seconds(1)) {
  heartbeat_.process = process_name;
  heartbeat_.pid = static_cast<int32_t>(getpid());
  heartbeat_.host = hostName();
  heartbeat_.last_firing_id = -1;
  heartbeat_.state = "idle";
}

void HeartbeatSender::update(bool arbiter_waiting) {
  const auto now = Clock::now();
  const bool answer_waiting = arbiter_waiting && now - last_waiting_answer_ > std::chrono::milliseconds(50);
  if (now < next_ && !answer_waiting) return;
  heartbeat_.utime = wallMicros();
  port_.publish(lcm_, heartbeat_);
  ++sent_;
  if (answer_waiting) last_waiting_answer_ = now;
  if (now >= next_) next_ += period_;
}

}  // namespace beft::service
