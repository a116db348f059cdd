// OMPL's geometric planners behind the common Planner interface, on the
// shared map and validity checker. Planners that stop at their first
// solution (RRTConnect, RRT, PRM) have it simplified with OMPL's
// PathSimplifier within the remaining budget; the asymptotically optimal ones
// (RRT*, InformedRRT*, BIT*, PRM*, ...) improve their path until the deadline.
//
// OMPL 1.5 seeds its random numbers once per process (ompl::RNG::setSeed
// before any planner exists), so setSeed() here has no effect; call
// seedOmpl() at start-up for reproducible sampling.
#pragma once

#include "planners/planner.hpp"

#include <ompl/base/Planner.h>
#include <ompl/base/SpaceInformation.h>

#include <string>
#include <vector>

namespace beft::planners {

// Names accepted after "ompl:" (e.g. RRTConnect, RRTstar, InformedRRTstar,
// BITstar, PRMstar).
std::vector<std::string> omplPlannerNames();
// Allocates one of them; throws std::invalid_argument for an unknown name.
ompl::base::PlannerPtr allocateOmplPlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si);

// Seeds OMPL's process-wide random numbers; only effective before any OMPL
// planner or sampler has been created. Also keeps OMPL to error messages.
void seedOmpl(uint64_t seed);

class OmplPlanner : public Planner {
 public:
  // ompl_name: one of omplPlannerNames(); throws std::invalid_argument otherwise.
  explicit OmplPlanner(std::string ompl_name);
  std::string name() const override { return "ompl:" + ompl_name_; }
  void clear() override;
  bool isAnytime() const override;
  // Makes asymptotically optimal planners return their first solution
  // instead of improving it until the deadline.
  void setStopAtFirstSolution(bool stop) { stop_at_first_ = stop; }

 protected:
  void setupMap() override;
  Path solvePath(Point2 start, Point2 goal, const Deadline& deadline, std::string& why_not) override;

 private:
  std::string ompl_name_;
  ompl::base::SpaceInformationPtr si_;
  ompl::base::PlannerPtr planner_;
  bool stop_at_first_ = false;
};

}  // namespace beft::planners
