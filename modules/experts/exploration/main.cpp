// beft-exploration: the exploration expert process (see --help).
#include "exploration_expert.hpp"
#include "run_expert.hpp"

int main(int argc, char** argv) {
  beft::exploration::ExplorationExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
