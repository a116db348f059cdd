// beft-planner: the planner service process (see --help, --interface).
#include "services/planner/planner_process.hpp"

int main(int argc, char** argv) {
  beft::planner_service::PlannerProcess planner;
  return beft::service::runServiceMain(argc, argv, planner);
}
