#include "planners/ompl_space.hpp"

#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace beft::planners {

namespace ob = ompl::base;

Point2 toPoint(const ob::State* state) {
  const auto* s = state->as<ob::RealVectorStateSpace::StateType>();
  return {s->values[0], s->values[1]};
}

void setState(ob::State* state, Point2 p) {
  auto* s = state->as<ob::RealVectorStateSpace::StateType>();
  s->values[0] = p.x;
  s->values[1] = p.y;
}

GridStateValidityChecker::GridStateValidityChecker(const ob::SpaceInformationPtr& si,
                                                   std::shared_ptr<const PlanningMap> map)
    : ob::StateValidityChecker(si), map_(std::move(map)) {
  specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::APPROXIMATE;
}

bool GridStateValidityChecker::isValid(const ob::State* state) const {
  return map_->pointFree(toPoint(state));
}

double GridStateValidityChecker::clearance(const ob::State* state) const {
  return map_->clearance(toPoint(state));
}

GridMotionValidator::GridMotionValidator(const ob::SpaceInformationPtr& si, std::shared_ptr<const PlanningMap> map)
    : ob::MotionValidator(si), map_(std::move(map)) {}

bool GridMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  const bool free = map_->segmentFree(toPoint(s1), toPoint(s2));
  if (free) ++valid_; else ++invalid_;
  return free;
}

bool GridMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                      std::pair<ob::State*, double>& last_valid) const {
  const Point2 a = toPoint(s1);
  const Point2 b = toPoint(s2);
  const double fraction = map_->freeFraction(a, b);
  if (fraction >= 1.0) {
    ++valid_;
    return true;
  }
  ++invalid_;
  last_valid.second = fraction;
  if (last_valid.first != nullptr) setState(last_valid.first, a + fraction * (b - a));
  return false;
}

ob::SpaceInformationPtr makeSpaceInformation(std::shared_ptr<const PlanningMap> map) {
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, 0);
  bounds.setHigh(0, map->width());
  bounds.setLow(1, 0);
  bounds.setHigh(1, map->height());
  space->setBounds(bounds);
  // Used by planners for their own step sizes (range): one cell in the map.
  space->setLongestValidSegmentFraction(1.0 / std::max(map->width(), map->height()));
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(std::make_shared<GridStateValidityChecker>(si, map));
  si->setMotionValidator(std::make_shared<GridMotionValidator>(si, map));
  si->setup();
  return si;
}

}  // namespace beft::planners
