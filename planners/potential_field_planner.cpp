#include "planners/potential_field_planner.hpp"

#include "planners/path_tools.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace beft::planners {
namespace {

constexpr double kPi = 3.14159265358979323846;

uint64_t splitMix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A small, fast generator (SplitMix64 stream): the same numbers on every
// platform, unlike the standard distributions.
class ParticleRandom {
 public:
  explicit ParticleRandom(uint64_t seed) : state_(seed) {}
  // Uniform on [-sqrt(3), sqrt(3)): zero mean, unit variance.
  double unitVariance() {
    state_ += 0x9e3779b97f4a7c15ULL;
    const double u = static_cast<double>(splitMix64(state_) >> 11) * 0x1.0p-53;
    return (2.0 * u - 1.0) * 1.7320508075688772;
  }

 private:
  uint64_t state_;
};

Path resample(const Path& path, double spacing) {
  if (path.size() < 2) return path;
  Path out{path.front()};
  double carried = 0;
  for (size_t i = 1; i < path.size(); ++i) {
    const double length = distance(path[i - 1], path[i]);
    double at = spacing - carried;
    while (at <= length) {
      out.push_back(path[i - 1] + (at / length) * (path[i] - path[i - 1]));
      at += spacing;
    }
    carried = length - (at - spacing);
  }
  if (distance(out.back(), path.back()) > 1e-9) out.push_back(path.back());
  return out;
}

// One step of the octile grid between cell centres, as in octile_search.
bool moveAllowed(const GridMap& grid, int x, int y, int dx, int dy) {
  if (grid.blocked(x + dx, y + dy)) return false;
  if (dx != 0 && dy != 0) return grid.free(x + dx, y) && grid.free(x, y + dy);
  return true;
}

}  // namespace

void PotentialFieldParams::declare(DeclaredParameters& p) {
  constexpr double kNoLimit = DeclaredParameters::kNoLimit;
  p.declareChoice("target", target,
                  {{"euclidean", TargetPotential::Euclidean}, {"paper", TargetPotential::Euclidean},
                   {"geodesic", TargetPotential::Geodesic}},
                  "target potential M_D: euclidean (the paper's) or geodesic (around obstacles, no local minima)");
  p.declare("particles", particles, 1, 100000, "particles emitted, N_P");
  p.declare("sigma", sigma, 0, kNoLimit, "Gaussian blur of M_O giving M_P [cells]", true);
  p.declare("target_weight", target_weight, 0, kNoLimit, "weight of unit(M_T)", true);
  p.declare("obstacle_weight", obstacle_weight, 0, kNoLimit, "weight of the scaled M_F");
  p.declare("noise", noise, 0, kNoLimit, "initial random component (RMS), relative to target_weight");
  p.declare("noise_decay", noise_decay, 0, kNoLimit,
            "the random component falls by 1/e in noise_decay / step steps [cells]", true);
  p.declare("noise_correlation", noise_correlation, 1, kNoLimit, "correlation time of the random component [steps]");
  p.declare("step", step, 0, 1, "particle step [cells]", true);
  p.declare("goal_tolerance", goal_tolerance, 0, kNoLimit,
            "distance at which a particle heads straight for the goal [cells]", true);
  p.declare("straightness_weight", straightness_weight, 0, kNoLimit, "cost of turning in the winner choice [cells/rad]");
  p.declare("stall_steps", stall_steps, 2, 1000000,
            "steps without headway that stop (or, geodesic, redirect) a particle");
  p.declare("max_travel", max_travel, 0, kNoLimit, "particle travel limit, in multiples of (width + height)", true);
}

void PotentialFieldParams::set(const std::string& name, const std::string& value) {
  DeclaredParameters declared;
  declare(declared);
  declared.set(name, value);
}

std::vector<std::string> PotentialFieldParams::names() {
  PotentialFieldParams defaults;
  DeclaredParameters declared;
  defaults.declare(declared);
  std::vector<std::string> names;
  for (const auto& info : declared.list())
    names.push_back(info.name + "=" + (info.name == "target" ? std::string("euclidean|geodesic") : info.default_value));
  return names;
}

double noiseRms(const PotentialFieldParams& params, long step) {
  return params.noise * std::exp(-static_cast<double>(step) * params.step / params.noise_decay);
}

double particleCost(const Path& trace, double straightness_weight) {
  return pathLength(trace) + straightness_weight * totalTurning(resample(trace, 2.0));
}

PotentialFieldPlanner::PotentialFieldPlanner(PotentialFieldParams params) : params_(params) {}

std::string PotentialFieldPlanner::name() const {
  if (!name_.empty()) return name_;
  return params_.target == TargetPotential::Geodesic ? "pf-geodesic" : "pf";
}

// M_F is made at the first query: the geodesic field's particles stay where
// its wavefront reached, so theirs is made per query over that region only.
void PotentialFieldPlanner::setupMap() { obstacle_force_ = VectorField(); }

float PotentialFieldPlanner::targetDistanceAt(int x, int y) const {
  const int row = y - target_origin_.y, column = x - target_origin_.x;
  if (row < 0 || column < 0 || row >= target_distance_.rows || column >= target_distance_.cols)
    return std::numeric_limits<float>::infinity();
  return target_distance_.at<float>(row, column);
}

double PotentialFieldPlanner::wavefrontAt(Point2 p) const {
  const int x = std::clamp(static_cast<int>(std::floor(p.x)), 0, map_->width() - 1);
  const int y = std::clamp(static_cast<int>(std::floor(p.y)), 0, map_->height() - 1);
  return targetDistanceAt(x, y);
}

bool PotentialFieldPlanner::canMove(Point2 from, Point2 to) const {
  if (!map_->segmentFree(from, to)) return false;
  // The geodesic wavefront covers only the region around the start.
  return params_.target != TargetPotential::Geodesic || std::isfinite(wavefrontAt(to));
}

Point2 PotentialFieldPlanner::tryMove(Point2 p, Point2 move) const {
  const Point2 full = p + move;
  if (canMove(p, full)) return full;
  // Slide along the obstacle: keep the larger free component of the move.
  const Point2 along_x{p.x + move.x, p.y};
  const Point2 along_y{p.x, p.y + move.y};
  const bool x_first = std::abs(move.x) >= std::abs(move.y);
  for (const Point2& q : x_first ? std::array<Point2, 2>{along_x, along_y} : std::array<Point2, 2>{along_y, along_x}) {
    if (distance(p, q) > 1e-6 && canMove(p, q)) return q;
  }
  return p;
}

// Moves p to its cell's centre, then to the free neighbouring cell with the
// lowest wavefront value. False when no neighbour is lower (p is in the goal
// cell, or the wavefront is undefined here).
bool PotentialFieldPlanner::stepDownWavefront(Point2& p, Path& trace) const {
  const GridMap& grid = map_->inflated();
  const int x = std::clamp(static_cast<int>(std::floor(p.x)), 0, grid.width() - 1);
  const int y = std::clamp(static_cast<int>(std::floor(p.y)), 0, grid.height() - 1);
  const float here = targetDistanceAt(x, y);
  if (!std::isfinite(here) || grid.blocked(x, y)) return false;
  int best_dx = 0, best_dy = 0;
  float best = here;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if ((dx == 0 && dy == 0) || !moveAllowed(grid, x, y, dx, dy)) continue;
      const float value = targetDistanceAt(x + dx, y + dy);
      if (value < best) {
        best = value;
        best_dx = dx;
        best_dy = dy;
      }
    }
  }
  if (best_dx == 0 && best_dy == 0) return false;
  const Point2 centre = cellCentre(x, y);
  if (distance(p, centre) > 1e-9) trace.push_back(centre);
  p = cellCentre(x + best_dx, y + best_dy);
  trace.push_back(p);
  return true;
}

// The deterministic part of a particle's step: unit(M_T) and the scaled M_F,
// weighted (the random component is added by the caller).
Point2 PotentialFieldPlanner::fieldDirection(Point2 p, Point2 goal, double force_scale, bool geodesic) const {
  Point2 toward = target_force_.at(p);
  double toward_norm = norm(toward);
  if (toward_norm < 1e-12) {  // flat spot of M_T (e.g. the goal cell): head straight for the goal
    toward = goal - p;
    toward_norm = std::max(norm(toward), 1e-12);
  }
  Point2 repulsion = force_scale * obstacle_force_.at(p);
  if (geodesic) {
    // Obstacles beside the goal must not push particles off it: the
    // repulsion fades out within 3 sigma of the goal.
    repulsion = std::min(1.0, distance(p, goal) / (3 * params_.sigma)) * repulsion;
  }
  return (params_.target_weight / toward_norm) * toward + params_.obstacle_weight * repulsion;
}

// Geodesic field: a particle without headway for stall_steps (or stuck)
// steps down the wavefront until below the best value reached so far, so
// every stall ends with real headway. False when it cannot (a stall).
bool PotentialFieldPlanner::keepGeodesicHeadway(Point2& p, Point2 goal, bool moved, double& best_wavefront,
                                                int& steps_without_headway, ParticleRun& run) const {
  const double value = wavefrontAt(p);
  if (value < best_wavefront) {
    best_wavefront = value;
    steps_without_headway = 0;
    return true;
  }
  if (moved && ++steps_without_headway < params_.stall_steps) return true;
  do {
    if (!stepDownWavefront(p, run.trace)) break;
    ++run.discrete_steps;
  } while (wavefrontAt(p) >= best_wavefront);
  if (wavefrontAt(p) >= best_wavefront) return wavefrontAt(p) == 0 && map_->segmentFree(p, goal);  // in the goal cell
  best_wavefront = wavefrontAt(p);
  steps_without_headway = 0;
  return true;
}

PotentialFieldPlanner::ParticleRun PotentialFieldPlanner::runParticle(int index, Point2 start, Point2 goal,
                                                                      const Deadline& deadline) const {
  ParticleRun run;
  run.trace.reserve(1024);
  run.trace.push_back(start);
  ParticleRandom rng(splitMix64(seed_ * 0x100000001b3ULL + static_cast<uint64_t>(index)));
  // r_t: stationary unit-variance components, so E|r|^2 = 2; scaled to unit RMS below.
  const double keep = std::exp(-1.0 / params_.noise_correlation);
  const double renew = std::sqrt(1.0 - keep * keep);
  Point2 random_drift{rng.unitVariance(), rng.unitVariance()};
  const bool geodesic = params_.target == TargetPotential::Geodesic;
  const double force_scale = params_.sigma * std::sqrt(2 * kPi);
  const double max_travel = params_.max_travel * (map_->width() + map_->height());
  const long max_steps = static_cast<long>(max_travel / params_.step) + 1;

  Point2 p = start;
  double best_wavefront = geodesic ? wavefrontAt(p) : 0.0;
  int steps_without_headway = 0;
  Point2 window_start = p;
  for (long step = 0; step < max_steps; ++step) {
    if ((step & 63) == 0 && deadline.expired()) {
      run.aborted = true;
      return run;
    }
    if (distance(p, goal) <= params_.goal_tolerance && map_->segmentFree(p, goal)) {
      run.trace.push_back(goal);
      run.arrived = true;
      return run;
    }
    random_drift = keep * random_drift + renew * Point2{rng.unitVariance(), rng.unitVariance()};
    // random_drift has an RMS length of sqrt(2): scaled to noiseRms.
    Point2 direction =
        fieldDirection(p, goal, force_scale, geodesic) + (noiseRms(params_, step) / std::sqrt(2.0)) * random_drift;
    const double magnitude = norm(direction);
    if (magnitude > 1) direction = (1 / magnitude) * direction;

    const Point2 next = tryMove(p, params_.step * direction);
    const bool moved = distance(next, p) > 1e-9;
    if (moved) {
      p = next;
      run.trace.push_back(p);
    }
    if (geodesic) {
      if (!keepGeodesicHeadway(p, goal, moved, best_wavefront, steps_without_headway, run)) {
        run.stalled = true;  // wavefront undefined here: give up
        return run;
      }
    } else if (++steps_without_headway >= params_.stall_steps) {
      // The paper's field: no headway over the window means a local minimum.
      if (distance(p, window_start) < 0.1 * params_.step * params_.stall_steps) {
        run.stalled = true;
        return run;
      }
      window_start = p;
      steps_without_headway = 0;
    }
  }
  return run;
}

Path PotentialFieldPlanner::solvePath(Point2 start, Point2 goal, const Deadline& deadline, std::string& why_not) {
  traces_.clear();
  const auto field_begin = Deadline::Clock::now();
  const GridCell goal_cell{static_cast<int>(std::floor(goal.x)), static_cast<int>(std::floor(goal.y))};
  if (params_.target == TargetPotential::Geodesic) {
    const GridCell start_cell{static_cast<int>(std::floor(start.x)), static_cast<int>(std::floor(start.y))};
    cv::Rect finite_region;
    target_distance_ = geodesicTargetDistance(map_->inflated(), goal_cell, start_cell, finite_region);
    target_origin_ = finite_region.tl();
    if (!std::isfinite(wavefrontAt(start))) {
      why_not = name() + ": goal unreachable from start";
      return {};
    }
    target_force_ = negativeGradientFinite(target_distance_, target_origin_);
    // Particles stay on finite cells; the region holds the cells around them too.
    obstacle_force_ = obstacleForce(map_->inflated(), params_.sigma, finite_region);
  } else {
    if (obstacle_force_.fx().empty() || obstacle_force_.fx().size() != cv::Size(map_->width(), map_->height()))
      obstacle_force_ = obstacleForce(map_->inflated(), params_.sigma, cv::Rect(0, 0, map_->width(), map_->height()));
    target_distance_ = euclideanTargetDistance(map_->width(), map_->height(), goal_cell);
    target_origin_ = cv::Point(0, 0);
    target_force_ = negativeGradient(target_distance_);
  }
  stats_["field_ms"] = std::chrono::duration<double, std::milli>(Deadline::Clock::now() - field_begin).count();

  int arrived = 0;
  int stalled = 0;
  int discrete_steps = 0;
  bool aborted = false;
  double best_cost = std::numeric_limits<double>::infinity();
  Path best;
  for (int i = 0; i < params_.particles; ++i) {
    ParticleRun run = runParticle(i, start, goal, deadline);
    discrete_steps += run.discrete_steps;
    stalled += run.stalled ? 1 : 0;
    if (run.arrived) {
      ++arrived;
      const double cost = particleCost(run.trace, params_.straightness_weight);
      if (cost < best_cost) {
        best_cost = cost;
        best = run.trace;
      }
    }
    traces_.push_back(std::move(run.trace));
    if (run.aborted) {
      aborted = true;
      break;
    }
  }
  stats_["particles"] = static_cast<double>(traces_.size());
  stats_["arrived"] = arrived;
  stats_["stalled"] = stalled;
  stats_["discrete_steps"] = discrete_steps;
  if (best.empty()) {
    why_not = aborted ? name() + ": deadline passed before any particle arrived"
                      : name() + ": no particle reached the goal (" + std::to_string(stalled) +
                            " trapped in local minima, " + std::to_string(traces_.size() - stalled) +
                            " out of steps)";
  }
  return best;
}

}  // namespace beft::planners
