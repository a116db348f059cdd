// beft-tasks: the task stack and executor process (see --help).
#include "lib/expert/run_expert.hpp"
#include "experts/tasks/tasks_expert.hpp"

int main(int argc, char** argv) {
  beft::tasks::TasksExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
