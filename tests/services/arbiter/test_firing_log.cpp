// The arbiter's firing log: readable lines, CSV rows, and when lines are flushed.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <string>

#include "lib/service/firing_trace.hpp"
#include "services/arbiter/firing_log.hpp"

using namespace beft::arbiter;

namespace {

FiringRecord record(int64_t tick, const std::string& expert) {
  FiringRecord r;
  r.tick = tick;
  r.firing_id = tick * 10 + 1;
  r.expert = expert;
  r.transition = "t_" + expert;
  r.attempt = 1;
  r.outcome = "ok";
  r.duration_s = 0.0015;
  r.expert_duration_s = 0.001;
  return r;
}

// What has reached the file behind a fully buffered stream so far.
std::string flushedText(std::FILE* file) {
  std::string text;
  char buffer[512];
  const int fd = fileno(file);
  for (off_t offset = 0;;) {
    const ssize_t n = pread(fd, buffer, sizeof(buffer), offset);
    if (n <= 0) break;
    text.append(buffer, static_cast<size_t>(n));
    offset += n;
  }
  return text;
}

}  // namespace

TEST(FiringLog, LinesSayTickFiringExpertOutcomeAndTimes) {
  const std::string line = formatFiringLine(record(12, "vision"));
  EXPECT_NE(line.find("tick    12"), std::string::npos) << line;
  EXPECT_NE(line.find("firing    121"), std::string::npos) << line;
  EXPECT_NE(line.find("vision"), std::string::npos) << line;
  EXPECT_NE(line.find("1.500 ms"), std::string::npos) << line;
  EXPECT_NE(line.find("(expert 1.000 ms)"), std::string::npos) << line;
}

// The viewer tells the trace from the other lines of the log with
// lib/service/firing_trace.hpp: it reads what this writes, and a firing that
// went wrong is not routine.
TEST(FiringLog, ItsLinesReadAsFiringTraceAndOnlyASmoothFiringAsRoutine) {
  const auto read = [](const FiringRecord& r) { return beft::service::readFiringTraceLine(formatFiringLine(r)); };
  FiringRecord smooth = record(12, "vision");
  EXPECT_TRUE(read(smooth).is_firing);
  EXPECT_TRUE(read(smooth).routine);
  smooth.expert_duration_s = -1.0;
  EXPECT_TRUE(read(smooth).routine);
  FiringRecord timed_out = record(7, "fusion");
  timed_out.outcome = "timeout";
  timed_out.action = "retry";
  timed_out.message = "no DONE within 5 s";
  EXPECT_TRUE(read(timed_out).is_firing);
  EXPECT_FALSE(read(timed_out).routine);
  FiringRecord retried = record(7, "fusion");
  retried.attempt = 2;
  EXPECT_FALSE(read(retried).routine);
  for (const char* other : {"", "tick", "tick 12 went well", "ticks 3  firing 4  x ok", "stopping after 300 ticks",
                            "tick 3  firings 4", "tick   3  firing"}) {
    EXPECT_FALSE(beft::service::readFiringTraceLine(other).is_firing) << other;
  }
}

TEST(FiringLog, LinesWaitForTheFlushPeriodOrAFlush) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  std::setvbuf(file, nullptr, _IOFBF, 1 << 16);
  {
    FiringLog log(file, "", 3600.0);  // no period ends during the test
    log.write(record(1, "world"));
    log.write(record(1, "vision"));
    EXPECT_EQ(flushedText(file), "") << "written before the period ended";
    log.flush();
    const std::string text = flushedText(file);
    EXPECT_NE(text.find("world"), std::string::npos) << text;
    EXPECT_NE(text.find("vision"), std::string::npos) << text;
  }
  std::fclose(file);
}

TEST(FiringLog, APeriodOfZeroWritesEveryLineAtOnce) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  std::setvbuf(file, nullptr, _IOFBF, 1 << 16);
  FiringLog log(file, "", 0.0);
  log.write(record(3, "tasks"));
  EXPECT_NE(flushedText(file).find("tasks"), std::string::npos);
  std::fclose(file);
}
