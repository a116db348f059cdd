// beft-vision: the low-level vision expert process (see --help).
#include "lib/expert/run_expert.hpp"
#include "experts/vision/vision_expert.hpp"

int main(int argc, char** argv) {
  beft::vision::VisionExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
