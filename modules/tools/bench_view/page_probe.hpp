// The viewer page in headless Chromium, by page_probe.mjs (node,
// puppeteer-core, Debian's chromium): started before the run so that the
// browser is up when the run's viewer begins to serve, it opens the page
// and prints window.beft's figures into a file, read here.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace beft::bench {

// One reading of window.beft.
struct PageSample {
  int64_t wall_ms = 0;  // when it was read [ms since the epoch]
  int64_t tick = -1;
  double frame_time_ms = 0;  // the page's rolling mean of animation-frame intervals
  int64_t frames = 0, renders = 0;
  int objects = 0, hypotheses = 0;
};

struct PageReadings {
  std::string unavailable;  // why the page could not be opened (no chromium, no puppeteer-core), or ""
  int64_t connected_ms = -1;  // when the page's WebSocket was open [ms since the epoch]
  std::vector<PageSample> samples;
  std::vector<std::string> page_errors;
};

// Where page_probe.mjs and its node_modules are (the build tree's share/beft/bench_view).
std::string probeFolder();
// Whether the page can be opened here: "" if so, else why not (the bridge, beft-control or the page not
// built; node, chromium or puppeteer-core missing).
std::string probeUnavailable(const std::string& work);

class PageProbe {
 public:
  // Starts the browser; it opens `url` once served, reads the page every
  // `every_ms` and stops after `seconds` (0: when stopped).
  PageProbe(const std::string& url, int every_ms, double seconds, const std::string& output_file);
  ~PageProbe();
  PageProbe(const PageProbe&) = delete;
  PageProbe& operator=(const PageProbe&) = delete;

  PageReadings readings() const;
  bool ended() const;
  // Closes the browser (SIGTERM: it closes itself) and waits for it.
  void stop();

 private:
  std::string output_file_;
  pid_t pid_ = -1;
  mutable bool ended_ = false;
};

PageReadings parseProbeOutput(const std::string& text);

}  // namespace beft::bench
