// beft-fusion: the high-level fusion expert process (see --help).
#include "experts/fusion/fusion_expert.hpp"
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::fusion::FusionExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
