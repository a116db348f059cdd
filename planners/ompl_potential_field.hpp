// The potential-field planner as an ompl::base::Planner, so OMPL's own tools
// (ompl::tools::Benchmark, SimpleSetup) run it beside OMPL's planners. It
// needs the PlanningMap the SpaceInformation was made from
// (makeSpaceInformation), since it plans on fields over the grid. Each solve()
// uses the next seed, so repeated benchmark runs see different particles.
#pragma once

#include "planners/planning_map.hpp"
#include "planners/potential_field_planner.hpp"

#include <ompl/base/Planner.h>

#include <memory>

namespace beft::planners {

class PotentialFieldOmplPlanner : public ompl::base::Planner {
 public:
  PotentialFieldOmplPlanner(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const PlanningMap> map,
                            PotentialFieldParams params = {}, uint64_t first_seed = 1);

  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  void clear() override;
  void setup() override;
  void getPlannerData(ompl::base::PlannerData& data) const override;

 private:
  std::shared_ptr<const PlanningMap> map_;
  PotentialFieldPlanner planner_;
  DeclaredParameters declared_;  // the planner's parameters, for OMPL's ParamSet
  bool map_ready_ = false;
  uint64_t next_seed_;
  Path last_path_;
};

}  // namespace beft::planners
