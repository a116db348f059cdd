// beft-exploration: the exploration expert process (see --help).
#include "experts/exploration/exploration_expert.hpp"
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::exploration::ExplorationExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
