// beft-geometry: the low-level geometry expert process (see --help).
#include "experts/geometry/geometry_expert.hpp"
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::geometry::GeometryExpert expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
