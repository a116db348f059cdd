// The bridge against the real SoundScape Renderer: JACK with its dummy driver
// (no sound card), ssr-binaural without GUI on Debian's default HRIRs and a
// port of its own, a short yard run with the bridge attached; then SSR's own
// reports, read by a second client, must show the scene's last state. And the
// bridge against a stand-in for SSR that is missing, goes away, and talks
// nonsense.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <thread>

#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/launch/free_port.hpp"
#include "lib/common/lcm_url.hpp"
#include "tests/system/run_support.hpp"
#include "services/ssr_bridge/ssr_conventions.hpp"
#include "services/ssr_bridge/ssr_updates.hpp"

using namespace beft::system_test;
using namespace beft::ssr_bridge;
using Clock = std::chrono::steady_clock;

namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

// A program in the background, in a process group of its own (SSR starts a
// player process per sound file), stopped with that whole group when this
// goes, whatever the test's outcome: SIGTERM, then SIGKILL after grace_s
// (SSR does not end on SIGTERM; a killed JACK server leaves its entry in
// JACK's registry, so JACK is given time to end).
class Background {
 public:
  Background(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
             const std::string& output, double grace_s = 3)
      : output_(output), grace_s_(grace_s) {
    pid_ = fork();
    if (pid_ == 0) {
      setpgid(0, 0);
      const int fd = open(output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
      std::vector<char*> args;
      for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
      args.push_back(nullptr);
      execvp(args[0], args.data());
      _exit(127);
    }
    setpgid(pid_, pid_);  // also here: no window in which a kill of the group misses it
  }
  ~Background() { stop(); }
  bool running() {
    if (pid_ <= 0) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) != pid_) return true;
    reaped_ = true;
    return false;
  }
  void stop() {
    if (pid_ <= 0) return;
    kill(-pid_, SIGTERM);
    const auto deadline = Clock::now() + std::chrono::duration<double>(grace_s_);
    while (running() && Clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    kill(-pid_, SIGKILL);  // the group: what the leader started, even if the leader is gone
    if (!reaped_) waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  std::string output() const { return readAll(output_); }

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
  std::string output_;
  double grace_s_;
};

// Polls `ready` every 50 ms until it holds or `seconds` pass.
bool waitFor(double seconds, const std::function<bool()>& ready) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < deadline) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return ready();
}

int freeTcpPort() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  if (bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    close(fd);
    return -1;
  }
  close(fd);
  return ntohs(address.sin_port);
}

int connectTo(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) return fd;
  close(fd);
  return -1;
}

// A client of SSR's network interface that keeps SSR's reports as a scene.
class SsrWatcher {
 public:
  explicit SsrWatcher(int port) : fd_(connectTo(port)) {}
  ~SsrWatcher() {
    if (fd_ >= 0) close(fd_);
  }
  bool connected() const { return fd_ >= 0; }
  // Reads what SSR sent for up to timeout_ms; false when SSR closed the connection.
  bool read(int timeout_ms) {
    pollfd pfd{fd_, POLLIN, 0};
    if (poll(&pfd, 1, timeout_ms) <= 0) return true;
    char buffer[65536];
    const ssize_t n = recv(fd_, buffer, sizeof buffer, 0);
    if (n <= 0) return false;
    std::vector<std::string> messages;
    splitter_.feed(buffer, static_cast<std::size_t>(n), messages);
    for (const auto& m : messages) applyUpdate(m, scene_);
    return true;
  }
  const SsrScene& scene() const { return scene_; }

 private:
  int fd_;
  MessageSplitter splitter_;
  SsrScene scene_;
};

double angleBetween(double a, double b) {
  const double d = std::fmod(std::fabs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

// "" when SSR's scene is the run's last state, else the first difference.
std::string differences(const SsrScene& ssr, const beft::scene_objects_t& objects, const beft::robot_state_t& robot) {
  std::ostringstream out;
  std::map<std::string, const SsrSource*> by_name;
  for (const auto& [number, source] : ssr.sources)
    if (!source.name.empty()) by_name[source.name] = &source;
  std::size_t acoustic = 0;
  for (const auto& object : objects.objects) {
    if (!object.has_acoustic) continue;
    ++acoustic;
    const auto it = by_name.find(object.id);
    if (it == by_name.end()) return "SSR has no source named " + object.id;
    const SsrSource& s = *it->second;
    if (!s.x || std::fabs(*s.x - object.x) > 0.01 || std::fabs(*s.y - object.y) > 0.01) {
      out << object.id << " at (" << (s.x ? *s.x : NAN) << ", " << (s.y ? *s.y : NAN) << "), not (" << object.x
          << ", " << object.y << ")";
      return out.str();
    }
    if (!s.mute || *s.mute == object.sound_active)
      return object.id + (object.sound_active ? " sounds but is muted" : " is silent but not muted");
    if (!s.volume_db || std::fabs(*s.volume_db - volumeDecibels(object.level)) > 0.05) {
      out << object.id << " volume " << (s.volume_db ? *s.volume_db : NAN) << " dB, not "
          << volumeDecibels(object.level);
      return out.str();
    }
  }
  if (by_name.size() != acoustic) {
    out << "SSR has " << by_name.size() << " named sources for " << acoustic << " acoustic objects";
    return out.str();
  }
  const double azimuth = robot.yaw + robot.head_yaw;
  if (!ssr.reference_x || std::fabs(*ssr.reference_x - robot.x) > 0.01 ||
      std::fabs(*ssr.reference_y - robot.y) > 0.01 || !ssr.reference_azimuth ||
      angleBetween(*ssr.reference_azimuth, azimuth) > 0.5) {
    out << "SSR's reference at (" << (ssr.reference_x ? *ssr.reference_x : NAN) << ", "
        << (ssr.reference_y ? *ssr.reference_y : NAN) << ") azimuth "
        << (ssr.reference_azimuth ? *ssr.reference_azimuth : NAN) << ", the head at (" << robot.x << ", " << robot.y
        << ") looking along " << azimuth;
    return out.str();
  }
  return "";
}

// yard.xml with the car's engine silent, beside the shipped sounds.
std::string yardWithASilentCar(const std::string& dir) {
  std::string yard = readAll(sourceDir() + "/scenarios/yard.xml");
  const std::string engine = "<acoustic sound=\"sounds/engine.wav\" active=\"1\"";
  const auto at = yard.find(engine);
  if (at == std::string::npos) return "";
  yard.replace(at, engine.size(), "<acoustic sound=\"sounds/engine.wav\" active=\"0\"");
  std::ofstream(dir + "/yard_silent_car.xml") << yard;
  if (symlink((sourceDir() + "/scenarios/sounds").c_str(), (dir + "/sounds").c_str()) != 0) return "";
  return dir + "/yard_silent_car.xml";
}

}  // namespace

TEST(SsrBridgeSystem, SsrShowsTheLastStateOfAYardRun) {
  for (const char* program : {"jackd", "jack_lsp", "ssr-binaural"})
    if (!onPath(program))
      GTEST_SKIP() << program << " is not installed (Debian: jackd2, soundscaperenderer-nox; ./beft setup)";
  const std::string dir = makeTempDir("ssr_bridge");
  // JACK keeps a registry of at most 8 servers in shared memory and frees
  // the entry of a server that died without unregistering (killed) only for
  // a server of the same name: names from a fixed few, each tried in turn,
  // so one another run is using is skipped and a dead one's is taken back.
  std::unique_ptr<Background> jack;
  std::string jack_name, jack_logs;
  std::map<std::string, std::string> jack_env;
  for (int slot = 0; slot < 8 && !jack; ++slot) {
    jack_name = "beft_ssr_test_" + std::to_string(slot);
    // JACK_NO_AUDIO_RESERVATION: no D-Bus device reservation (none in a container);
    // JACK_NO_START_SERVER: a client never starts a server of its own.
    jack_env = {{"JACK_DEFAULT_SERVER", jack_name}, {"JACK_NO_AUDIO_RESERVATION", "1"}, {"JACK_NO_START_SERVER", "1"}};
    const std::string log = dir + "/jackd_" + std::to_string(slot) + ".log";
    jack = std::make_unique<Background>(
        std::vector<std::string>{"jackd", "-n", jack_name, "--no-realtime", "-d", "dummy", "-r", "44100", "-p", "1024"},
        jack_env, log, /*grace_s=*/10);
    const std::string jack_lsp = "JACK_DEFAULT_SERVER=" + jack_name + " JACK_NO_START_SERVER=1 jack_lsp";
    bool up = waitFor(20, [&] { return !jack->running() || runCommand(jack_lsp, 5).exit_code == 0; });
    // Still running a moment later: jack_lsp did not answer for a server of
    // this name that another run has (this one then gives up).
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    up = up && jack->running();
    if (!up) {
      jack_logs += jack_name + ":\n" + jack->output() + "\n";
      jack.reset();
    }
  }
  ASSERT_TRUE(jack) << "JACK did not start under any of the names tried:\n" << jack_logs;

  const int ssr_port = freeTcpPort();
  ASSERT_GT(ssr_port, 0);
  Background ssr({"ssr-binaural", "--ip-server=" + std::to_string(ssr_port), "--no-gui", "--no-tracker", "--loop"},
                 jack_env, dir + "/ssr.log");
  ASSERT_TRUE(waitFor(30, [&] {
    if (!ssr.running()) return true;
    const int fd = connectTo(ssr_port);
    if (fd >= 0) close(fd);
    return fd >= 0;
  }) && ssr.running()) << "SSR did not start listening on port " << ssr_port << ":\n" << ssr.output();

  const std::string scenario = yardWithASilentCar(dir);
  ASSERT_FALSE(scenario.empty()) << "cannot write the scenario into " << dir;
  const auto run = runCommand(binDir() + "/beft-run " + scenario + " --max-ticks 30 --no-report --out " + dir +
                                  "/run --ssr --set ssr_server_host=127.0.0.1 --set ssr_port=" +
                                  std::to_string(ssr_port),
                              180);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string processes = readAll(dir + "/run/processes.log");
  EXPECT_NE(processes.find("[ssr_bridge] [ssr_bridge] info: connected to SSR at 127.0.0.1:" + std::to_string(ssr_port)),
            std::string::npos)
      << processes;

  const auto log = readLog(dir + "/run/run.lcmlog");
  const auto objects = messagesOn<beft::scene_objects_t>(log, "GT_OBJECTS");
  const auto robots = messagesOn<beft::robot_state_t>(log, "ROBOT_STATE");
  ASSERT_FALSE(objects.empty());
  ASSERT_FALSE(robots.empty());
  const auto& last_objects = objects.back();
  const auto& last_robot = robots.back();
  int sounding = 0, silent = 0;
  for (const auto& o : last_objects.objects)
    if (o.has_acoustic) ++(o.sound_active ? sounding : silent);
  ASSERT_EQ(sounding, 2);  // the hidden victim and the siren
  ASSERT_EQ(silent, 1);    // the car

  // SSR makes a source in about two seconds (it starts a player for the
  // file) and works through the bridge's requests in order: its reports are
  // read until they show the run's end, or for 40 s.
  SsrWatcher watcher(ssr_port);
  ASSERT_TRUE(watcher.connected()) << "SSR's log:\n" << ssr.output() << "\nJACK's log:\n" << jack->output();
  std::string difference = "nothing read from SSR";
  const auto deadline = Clock::now() + std::chrono::seconds(40);
  while (Clock::now() < deadline) {
    ASSERT_TRUE(watcher.read(200)) << "SSR closed the connection:\n" << ssr.output();
    if (watcher.scene().state_received &&
        (difference = differences(watcher.scene(), last_objects, last_robot)).empty())
      break;
  }
  EXPECT_EQ(difference, "") << "SSR's log:\n" << ssr.output() << "\nJACK's log:\n" << jack->output();
  EXPECT_TRUE(ssr.running()) << ssr.output();
  std::printf("[test] the run's last tick %lld; the head at (%.3f, %.3f) looking along %.2f deg; SSR agrees\n",
              static_cast<long long>(last_robot.tick), last_robot.x, last_robot.y,
              last_robot.yaw + last_robot.head_yaw);
}

namespace {

// A stand-in for SSR: listens, accepts, keeps what it was sent.
class FakeSsr {
 public:
  explicit FakeSsr(int port) {
    listener_ = socket(AF_INET, SOCK_STREAM, 0);
    const int one = 1;
    setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || listen(listener_, 4) != 0) {
      close(listener_);
      listener_ = -1;
    }
  }
  ~FakeSsr() {
    drop();
    if (listener_ >= 0) close(listener_);
  }
  bool listening() const { return listener_ >= 0; }
  bool accept(double seconds) {
    pollfd pfd{listener_, POLLIN, 0};
    if (poll(&pfd, 1, static_cast<int>(seconds * 1000)) <= 0) return false;
    client_ = ::accept(listener_, nullptr, nullptr);
    received_.clear();
    return client_ >= 0;
  }
  // Reads what came until `seen` holds or `seconds` pass.
  bool receiveUntil(double seconds, const std::function<bool(const std::string&)>& seen) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (!seen(received_) && Clock::now() < deadline) {
      pollfd pfd{client_, POLLIN, 0};
      if (poll(&pfd, 1, 50) <= 0) continue;
      char buffer[65536];
      const ssize_t n = recv(client_, buffer, sizeof buffer, 0);
      if (n <= 0) return false;
      received_.append(buffer, static_cast<std::size_t>(n));
    }
    return seen(received_);
  }
  void send(const std::string& bytes) { ::send(client_, bytes.data(), bytes.size(), MSG_NOSIGNAL); }
  void drop() {
    if (client_ >= 0) close(client_);
    client_ = -1;
  }
  const std::string& received() const { return received_; }

 private:
  int listener_ = -1, client_ = -1;
  std::string received_;
};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(SsrBridgeSystem, OutlivesAMissingAVanishingAndANonsensicalSsr) {
  const std::string dir = makeTempDir("ssr_bridge_fake");
  const int lcm_port = beft::launch::findFreeUdpPort();
  const int ssr_port = freeTcpPort();
  ASSERT_GT(lcm_port, 0);
  ASSERT_GT(ssr_port, 0);
  const std::string url = beft::lcmUrlForPort(lcm_port);
  Background bridge({binDir() + "/beft-ssr-bridge", "--lcm-url", url, "--ssr-host", "localhost", "--ssr-port",
                     std::to_string(ssr_port), "--batch-ms", "5"},
                    {}, dir + "/bridge.log");
  // A scene of one sounding object, published as the world would, all along.
  lcm::LCM lcm(url);
  ASSERT_TRUE(lcm.good());
  beft::scene_objects_t objects{};
  beft::scene_object_t radio{};
  radio.id = "radio <1>";
  radio.has_acoustic = radio.sound_active = true;
  radio.sound = "/sounds/radio.wav";
  radio.level = 1.0;
  objects.objects = {radio};
  objects.num_objects = 1;
  beft::robot_state_t robot{};
  std::atomic<bool> publishing{true};
  std::thread world([&] {
    for (int tick = 0; publishing; ++tick) {
      objects.tick = robot.tick = tick;
      objects.objects[0].x = 0.01 * tick;  // moving
      lcm.publish("GT_OBJECTS", &objects);
      lcm.publish("ROBOT_STATE", &robot);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  });
  struct StopWorld {
    std::atomic<bool>& flag;
    std::thread& thread;
    ~StopWorld() {
      flag = false;
      thread.join();
    }
  } stop_world{publishing, world};

  // SSR missing: the bridge says so and keeps trying.
  ASSERT_TRUE(waitFor(30, [&] { return bridge.output().find("SSR is not reachable") != std::string::npos; }))
      << bridge.output();
  ASSERT_TRUE(bridge.running()) << bridge.output();
  FakeSsr ssr(ssr_port);
  ASSERT_TRUE(ssr.listening());
  const std::string made = "name=\"radio &lt;1&gt;\" file=\"/sounds/radio.wav\"";
  ASSERT_TRUE(ssr.accept(10)) << bridge.output();
  ASSERT_TRUE(ssr.receiveUntil(10, [&](const std::string& r) { return r.find(made) != std::string::npos; }))
      << ssr.received();
  EXPECT_EQ(ssr.received().rfind("<request><scene clear=\"true\"/></request>", 0), 0u) << ssr.received();
  // It keeps moving the radio, by number, one request per change.
  ASSERT_TRUE(ssr.receiveUntil(10, [](const std::string& r) { return count(r, "<request><source id=\"1\">") >= 3; }))
      << ssr.received();
  for (std::size_t at = 0; (at = ssr.received().find("<request>", at)) != std::string::npos; ++at)
    EXPECT_TRUE(at == 0 || ssr.received()[at - 1] == '\0') << "requests end with a binary zero";

  // Nonsense from "SSR": garbage, a message never ended, a huge one; then it goes away.
  std::mt19937 random(3);
  std::string garbage;
  for (int i = 0; i < 100000; ++i) garbage += static_cast<char>(random() % 256);
  ssr.send(garbage);
  ssr.send(std::string(1, '\0') + "<update><source id='1' name='radio <1>'/></update>" + std::string(1, '\0'));
  ssr.send("<update><source id='1' name='radio &lt;1&gt;'/></update>" + std::string(1, '\0'));
  ssr.send(std::string(3 << 20, 'x'));  // no zero: longer than any message
  ASSERT_TRUE(ssr.receiveUntil(5, [](const std::string& r) { return count(r, "<request><source id=\"1\">") >= 6; }))
      << "the bridge stopped sending:\n" << bridge.output();
  ssr.drop();

  // Back: the bridge connects again, clears and makes the source again.
  ASSERT_TRUE(ssr.accept(10)) << bridge.output();
  ASSERT_TRUE(ssr.receiveUntil(10, [&](const std::string& r) { return r.find(made) != std::string::npos; }))
      << ssr.received();
  EXPECT_EQ(ssr.received().rfind("<request><scene clear=\"true\"/></request>", 0), 0u);
  ASSERT_TRUE(bridge.running()) << bridge.output();
  bridge.stop();
  const std::string output = bridge.output();
  EXPECT_EQ(count(output, "SSR is not reachable"), 1u) << output;  // said once, not every second
  EXPECT_EQ(count(output, "lost the connection to SSR"), 1u) << output;
  EXPECT_EQ(count(output, "connected to SSR"), 2u) << output;
}
