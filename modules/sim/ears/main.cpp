// beft-ears: the robot's two ears, rendered each tick (see --help).
#include "sim/ears/ears_expert.hpp"
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::ears::EarsExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
