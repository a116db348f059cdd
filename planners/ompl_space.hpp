// OMPL's view of a PlanningMap: a 2-D real vector space over [0, width] x
// [0, height] (cell units), whose state validity and motion checks are the
// PlanningMap's own, so OMPL planners see exactly the obstacles the other
// planners see.
#pragma once

#include "planners/geometry.hpp"
#include "planners/planning_map.hpp"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>

#include <memory>

namespace beft::planners {

class GridStateValidityChecker : public ompl::base::StateValidityChecker {
 public:
  GridStateValidityChecker(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const PlanningMap> map);
  bool isValid(const ompl::base::State* state) const override;
  double clearance(const ompl::base::State* state) const override;

 private:
  std::shared_ptr<const PlanningMap> map_;
};

// Exact segment checks (every touched cell) instead of OMPL's sampling at a
// fixed resolution, so no motion clips a corner between samples.
class GridMotionValidator : public ompl::base::MotionValidator {
 public:
  GridMotionValidator(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const PlanningMap> map);
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

 private:
  std::shared_ptr<const PlanningMap> map_;
};

// A set-up SpaceInformation over the map.
ompl::base::SpaceInformationPtr makeSpaceInformation(std::shared_ptr<const PlanningMap> map);

Point2 toPoint(const ompl::base::State* state);
void setState(ompl::base::State* state, Point2 p);

}  // namespace beft::planners
