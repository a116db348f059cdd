#include "tools/bench_view/speed_rows.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "lib/launch/tcp_port.hpp"
#include "tools/bench_view/yard_runs.hpp"

namespace beft::bench {

namespace {

struct Row {
  int round = 0;
  bool viewed = false;
  YardRun run;
};

// Both kinds are measured from the same tick, the later of the two runs'
// first ticks after their hold: the loop's speed differs along the mission.
int64_t fromTick(const std::vector<Row>& round) {
  int64_t from = 0;
  for (const auto& row : round) from = std::max(from, row.run.resumed_at_tick);
  return from;
}

void printRow(const Row& row, int64_t from, double ticks_per_s) {
  char cpu[32] = "-";
  if (row.run.bridge_cpu_s >= 0) std::snprintf(cpu, sizeof(cpu), "%.2f", row.run.bridge_cpu_s);
  std::printf("%-8s %-4d %-6s %6.1f %9lld %9.0f %10s %13s%s%s\n", row.viewed ? "viewed" : "plain", row.round,
              row.viewed ? "yes" : "no", row.run.held_s, static_cast<long long>(from), ticks_per_s,
              row.run.bridge_rss_kb > 0 ? std::to_string(row.run.bridge_rss_kb / 1024).c_str() : "-", cpu,
              row.run.problem.empty() ? "" : "  (", row.run.problem.empty() ? "" : (row.run.problem + ")").c_str());
  std::fflush(stdout);
}

struct Mean {
  double sum = 0;
  int count = 0;
  void add(double value) {
    if (value > 0) sum += value, ++count;
  }
  double value() const { return count > 0 ? sum / count : 0; }
};

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t half = values.size() / 2;
  return values.size() % 2 ? values[half] : (values[half - 1] + values[half]) / 2;
}

// The ratio of the means is the verdict; the median of the turns' own
// ratios says how much one turn of a noisy machine moved it.
void printVerdict(const Mean& plain, const Mean& viewed, const std::vector<double>& turn_ratios) {
  if (plain.count == 0 || viewed.count == 0) {
    std::printf("\nviewed / plain: not measured (no run of one kind completed)\n");
    return;
  }
  const double share = viewed.value() / plain.value();
  std::printf("\nviewed / plain: %.3f of the ticks per second (%.0f against %.0f, means of %d and %d runs; median of "
              "the %zu turns' ratios %.3f): %s (target >= %.2f)\n",
              share, viewed.value(), plain.value(), viewed.count, plain.count, turn_ratios.size(),
              median(turn_ratios), share >= kTargetShare ? "target met" : "target NOT met", kTargetShare);
}

}  // namespace

int freeTcpPort() { return launch::findFreeTcpPort(); }

void runSpeedRows(const ViewOptions& o, bool viewer) {
  std::printf("yard.xml, up to %d ticks, --fast, seed %lld; each run held at its start for at least %.0f s (a "
              "viewed one until its page had connected and settled); ticks/s of the lockstep loop from the tick "
              "given on (the later of the turn's two first ticks after the hold)\n",
              o.ticks, o.seed, o.hold_s);
  std::printf("%-8s %-4s %-6s %6s %9s %9s %10s %13s\n", "run", "turn", "viewer", "held s", "from tick", "ticks/s",
              "bridge MB", "bridge CPU s");
  Mean plain, viewed;
  std::vector<double> turn_ratios;
  for (int round = 1; round <= o.repeat; ++round) {
    std::vector<Row> rows;  // plain first in odd turns, viewed first in even ones
    for (const bool with_viewer : {round % 2 == 0, round % 2 != 0}) {
      if (with_viewer && !viewer) continue;
      const std::string dir = o.work + "/" + (with_viewer ? "viewed_" : "plain_") + std::to_string(round);
      const int view_port = with_viewer ? freeTcpPort() : 0;
      rows.push_back({round, with_viewer, runYard({BEFT_SOURCE_DIR, dir, o.ticks, o.seed, view_port, o.hold_s})});
    }
    const int64_t from = fromTick(rows);
    double turn[2] = {0, 0};  // plain, viewed
    for (const auto& row : rows) {
      const double ticks_per_s = row.run.completed ? row.run.times.ticksPerSecondFrom(from) : 0;
      printRow(row, from, ticks_per_s);
      (row.viewed ? viewed : plain).add(ticks_per_s);
      turn[row.viewed ? 1 : 0] = ticks_per_s;
    }
    if (turn[0] > 0 && turn[1] > 0) turn_ratios.push_back(turn[1] / turn[0]);
  }
  if (viewer) printVerdict(plain, viewed, turn_ratios);
}

}  // namespace beft::bench
