// The paper's particle potential-field planner (section 3.1, spec/model.md).
//
// Per map: M_P = normalised Gaussian blur (sigma cells) of the inflated
// obstacle grid; M_F = -grad M_P. Per query: M_D = normalised distance to the
// target, M_T = -grad M_D. N_P particles leave the start; each step a
// particle moves by `step` cells along
//     target_weight * unit(M_T) + obstacle_weight * (sigma sqrt(2 pi)) M_F
//     + noise * exp(-t step / noise_decay) * r_t
// (clipped to unit length), where t counts the particle's steps and r_t is a
// random vector with unit RMS length, correlated over noise_correlation steps
// (an Ornstein-Uhlenbeck process): the random component decays over time, and
// while it lasts it drives each particle its own way round obstacles instead
// of averaging out step by step. M_T enters as a direction: its magnitude,
// 1/max(M_D) per cell, carries no information. The factor sigma sqrt(2 pi)
// scales M_F so that the edge of a thick obstacle pushes with about 1. A step
// into an obstacle slides along x or y, or waits. The winner among the
// particles that reach the goal minimises
//     length + straightness_weight * total turning (path resampled every 2 cells).
//
// Two target potentials:
//  - Euclidean (the paper's, default): the distance transform to the target
//    ignoring obstacles. The combined field has local minima (a U-shaped
//    obstacle facing the start traps every particle once the noise has
//    decayed); a particle that stops making headway fails.
//  - Geodesic: the octile wavefront to the target around obstacles, which
//    has no local minima. The wavefront spreads from the target to 1.5 times
//    the start's distance plus 20 cells, and particles stay inside it. The
//    repulsion fades out within 3 sigma of the goal, so a goal beside an
//    obstacle stays reachable. A particle that has not lowered its wavefront
//    value for `stall_steps` steps, or cannot move, steps down to lower
//    neighbouring cells until below its best value so far, so every particle
//    reaches a reachable goal.
#pragma once

#include "lib/common/declared_parameters.hpp"
#include "planners/octile_search.hpp"
#include "planners/planner.hpp"
#include "planners/potential_fields.hpp"

#include <string>
#include <vector>

namespace beft::planners {

enum class TargetPotential { Euclidean, Geodesic };

struct PotentialFieldParams {
  TargetPotential target = TargetPotential::Euclidean;
  int particles = 100;               // N_P
  double sigma = 3.0;                // Gaussian blur of M_O [cells]
  double target_weight = 1.0;        // weight of unit(M_T)
  double obstacle_weight = 2.0;      // weight of the scaled M_F
  double noise = 2.0;                // initial random component (RMS), relative to target_weight
  double noise_decay = 100.0;        // the random component falls by 1/e in noise_decay / step steps [cells]
  double noise_correlation = 100.0;  // correlation time of the random component [steps]
  double step = 1.0;                 // particle step [cells]
  double goal_tolerance = 1.5;       // distance at which a particle heads straight for the goal [cells]
  double straightness_weight = 2.0;  // cost of turning in the winner choice [cells/rad]
  int stall_steps = 40;              // steps without headway that stop (or, geodesic, redirect) a particle
  double max_travel = 4.0;           // particle travel limit, in multiples of (width + height)

  // Declares every member above by its name, with its range and meaning
  // (the defaults are the initialisers above).
  void declare(DeclaredParameters& parameters);
  // Sets one parameter by name through those declarations. Throws
  // std::invalid_argument naming the parameter and its range.
  void set(const std::string& name, const std::string& value);
  // "name=default" pairs for --help.
  static std::vector<std::string> names();
};

class PotentialFieldPlanner : public Planner {
 public:
  explicit PotentialFieldPlanner(PotentialFieldParams params = {});

  std::string name() const override;
  // The name it answers under ("pf-paper": the factory's paper mode).
  void setName(std::string name) { name_ = std::move(name); }
  void setSeed(uint64_t seed) override { seed_ = seed; }
  const PotentialFieldParams& params() const { return params_; }
  // Changes take effect at the next solve; sigma at the next setup.
  PotentialFieldParams& params() { return params_; }

  // Every particle's trace of the last solve, for pictures.
  const std::vector<Path>& particleTraces() const { return traces_; }
  // M_D of the last query (for pictures and tests): the geodesic one over
  // its region only, whose top-left cell is targetDistanceOrigin().
  const cv::Mat& targetDistanceMap() const { return target_distance_; }
  cv::Point targetDistanceOrigin() const { return target_origin_; }

 protected:
  void setupMap() override;
  Path solvePath(Point2 start, Point2 goal, const Deadline& deadline, std::string& why_not) override;

 private:
  struct ParticleRun {
    Path trace;
    bool arrived = false;
    bool aborted = false;  // the deadline passed
    bool stalled = false;  // stopped making headway (a local minimum)
    int discrete_steps = 0;
  };
  ParticleRun runParticle(int index, Point2 start, Point2 goal, const Deadline& deadline) const;
  bool stepDownWavefront(Point2& p, Path& trace) const;
  Point2 fieldDirection(Point2 p, Point2 goal, double force_scale, bool geodesic) const;
  bool keepGeodesicHeadway(Point2& p, Point2 goal, bool moved, double& best_wavefront, int& steps_without_headway,
                           ParticleRun& run) const;
  double wavefrontAt(Point2 p) const;
  float targetDistanceAt(int x, int y) const;  // +infinity outside M_D's region
  Point2 tryMove(Point2 p, Point2 move) const;
  bool canMove(Point2 from, Point2 to) const;

  PotentialFieldParams params_;
  std::string name_;  // "" for pf / pf-geodesic by the target potential
  uint64_t seed_ = 1;
  VectorField obstacle_force_;  // M_F: of the whole map, or (geodesic) of the last query's region
  cv::Mat target_distance_;  // M_D of the last query
  cv::Point target_origin_;  // the grid cell of its element (0, 0)
  VectorField target_force_;    // M_T of the last query
  std::vector<Path> traces_;
};

// Winner cost of a particle path: length + weight * turning of the path
// resampled every 2 cells. The particle of lowest cost among those that
// reach the goal wins (the first of equals).
double particleCost(const Path& trace, double straightness_weight);

// RMS length of the random component at a particle's step t (from 0):
// noise * exp(-t step / noise_decay): with the defaults, 2.0 falling by 1/e
// every 100 cells travelled.
double noiseRms(const PotentialFieldParams& params, long step);

}  // namespace beft::planners
