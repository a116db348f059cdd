#include "planners/synthetic_maps.hpp"

namespace beft::planners {

SyntheticCase simpleWallCase() {
  SyntheticCase c{"wall", GridMap(40, 30), {}};
  c.map.fillRect(20, 5, 21, 24);  // open above and below
  c.queries = {{cellCentre(8, 15), cellCentre(32, 15)}, {cellCentre(32, 12), cellCentre(6, 18)}};
  return c;
}

SyntheticCase uTrapCase() {
  SyntheticCase c{"u-trap", GridMap(64, 64), {}};
  c.map.fillRect(38, 16, 41, 47);  // bottom of the U, across the straight line
  c.map.fillRect(20, 16, 41, 18);  // lower arm
  c.map.fillRect(20, 45, 41, 47);  // upper arm; the opening faces the start
  c.queries = {{cellCentre(8, 32), cellCentre(56, 32)}, {cellCentre(30, 31), cellCentre(56, 34)}};
  return c;
}

SyntheticCase narrowGapCase() {
  SyntheticCase c{"narrow-gap", GridMap(64, 48), {}};
  c.map.fillRect(31, 0, 33, 47);
  c.map.fillRect(31, 34, 33, 35, false);  // a two-cell gap, off the straight line
  c.queries = {{cellCentre(10, 12), cellCentre(54, 12)}, {cellCentre(54, 40), cellCentre(8, 20)}};
  return c;
}

SyntheticCase combCase() {
  SyntheticCase c{"comb", GridMap(80, 48), {}};
  for (int x = 16; x <= 64; x += 8) c.map.fillRect(x, 0, x + 1, 36);  // teeth up from the bottom edge
  c.queries = {{cellCentre(4, 20), cellCentre(76, 20)}, {cellCentre(75, 6), cellCentre(5, 10)}};
  return c;
}

std::vector<SyntheticCase> syntheticTrapCases() { return {uTrapCase(), narrowGapCase(), combCase()}; }

}  // namespace beft::planners
