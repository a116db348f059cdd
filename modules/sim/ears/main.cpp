// beft-ears: the robot's two ears, rendered each tick (see --help).
#include "ears_expert.hpp"
#include "run_expert.hpp"

int main(int argc, char** argv) {
  beft::ears::EarsExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
