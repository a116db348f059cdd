#include "lib/wire/run_identity.hpp"

#include <sys/random.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>

#include "lib/common/log.hpp"

namespace beft::wire {

namespace {

std::atomic<int64_t> g_run_id{0};
std::once_flag g_from_environment;

void readEnvironment() {
  std::call_once(g_from_environment, [] {
    const char* text = std::getenv("BEFT_RUN_ID");
    if (text == nullptr || *text == '\0') return;
    try {
      g_run_id.store(parseRunId(text));
    } catch (const std::invalid_argument&) {
      // Refused where it is set (the launcher); a bad value means no run.
    }
  });
}

}  // namespace

int64_t runId() {
  readEnvironment();
  return g_run_id.load(std::memory_order_relaxed);
}

void setRunId(int64_t id) {
  readEnvironment();  // so that a later first call does not overwrite it
  g_run_id.store(id);
}

int64_t parseRunId(const std::string& text) {
  std::size_t used = 0;
  long long value = -1;
  try {
    value = std::stoll(text, &used, 16);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || value < 0)
    throw std::invalid_argument("run id '" + text + "' is not a hexadecimal number (as channels show it after '@')");
  return value;
}

int64_t freshRunId() {
  while (true) {
    uint64_t bits = 0;
    const ssize_t got = getrandom(&bits, sizeof bits, 0);
    if (got < 0 && errno == EINTR) continue;
    if (got != static_cast<ssize_t>(sizeof bits))
      throw std::runtime_error(std::string("cannot draw a run id: getrandom: ") + std::strerror(errno));
    const int64_t id = static_cast<int64_t>(bits >> 1);  // > 0 as parseRunId and the channel suffix take it
    if (id != 0) return id;
  }
}

int64_t runDescriptionHash(const std::string& description) {
  uint64_t hash = 1469598103934665603ull;  // FNV-1a
  for (unsigned char c : description) hash = (hash ^ c) * 1099511628211ull;
  const int64_t id = static_cast<int64_t>(hash >> 1);  // >= 0
  return id == 0 ? 1 : id;
}

namespace {

constexpr const char* kDescriptionVariable = "BEFT_RUN_DESCRIPTION";
constexpr const char* kStartedVariable = "BEFT_RUN_STARTED";

int64_t numberIn(const char* name, int base) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return 0;
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text, &end, base);
  return errno == 0 && *end == '\0' && value > 0 ? value : 0;  // malformed: not given
}

}  // namespace

RunOrigin runOrigin() { return {numberIn(kDescriptionVariable, 16), numberIn(kStartedVariable, 10)}; }

void setRunOriginEnvironment(const RunOrigin& origin) {
  if (origin.description != 0) setenv(kDescriptionVariable, runIdText(origin.description).c_str(), 1);
  else unsetenv(kDescriptionVariable);
  if (origin.started_utime != 0) setenv(kStartedVariable, std::to_string(origin.started_utime).c_str(), 1);
  else unsetenv(kStartedVariable);
}

std::string runOriginAssignments(const RunOrigin& origin) {
  std::string text;
  if (origin.description != 0) text += std::string(kDescriptionVariable) + "=" + runIdText(origin.description);
  if (origin.started_utime != 0)
    text += (text.empty() ? "" : " ") + std::string(kStartedVariable) + "=" + std::to_string(origin.started_utime);
  return text;
}

bool isUrlWideChannel(std::string_view channel) {
  return channel == "BEFT_RUNS" || channel.substr(0, 4) == "LCM_";
}

std::string runChannel(const std::string& channel, int64_t run_id) {
  std::string name = channel;
  if (run_id == 0 || isUrlWideChannel(channel)) return name;
  char suffix[24];
  std::snprintf(suffix, sizeof suffix, "@%llx", static_cast<unsigned long long>(run_id));
  return name + suffix;
}

std::string runChannel(const std::string& channel) { return runChannel(channel, runId()); }

const std::string& RunChannelNames::of(const std::string& channel) {
  const int64_t run = runId();
  if (run != run_id_) {
    names_.clear();
    run_id_ = run;
  }
  auto it = names_.find(channel);
  if (it == names_.end()) it = names_.emplace(channel, runChannel(channel, run)).first;
  return it->second;
}

std::string runIdText(int64_t run_id) {
  char text[20];
  std::snprintf(text, sizeof text, "%llx", static_cast<unsigned long long>(run_id));
  return text;
}

void logRunOf(const std::string& lcm_url) {
  if (runId() != 0) {
    log::info("in ", describeRun(runId()), " (its channels end in ", runChannel("", runId()), ")");
  } else if (lcm_url.rfind("udpm://", 0) == 0) {
    log::info("no BEFT_RUN_ID: on the plain channel names; to join a run started by beft run or beft launch, "
              "start this process with the command line the launcher prints (BEFT_RUN_ID=...)");
  }
}

std::string describeRun(int64_t run_id) { return run_id == 0 ? "no run id" : "run " + runIdText(run_id); }

RunChannel splitRunChannel(std::string_view channel) {
  const auto at = channel.rfind('@');
  if (at == std::string_view::npos || at + 1 >= channel.size() || channel.size() - at - 1 > 16) return {channel, 0};
  uint64_t id = 0;
  for (char c : channel.substr(at + 1)) {
    int digit;
    if (c >= '0' && c <= '9') digit = c - '0';
    else if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
    else return {channel, 0};
    id = id * 16 + static_cast<uint64_t>(digit);
  }
  if (id == 0 || id > static_cast<uint64_t>(INT64_MAX)) return {channel, 0};
  return {channel.substr(0, at), static_cast<int64_t>(id)};
}

}  // namespace beft::wire
