// Frame compression measured on a scenario's own frames (./beft bench camera):
// payload bytes per frame and CPU time to pack and unpack, for each packing of
// each encoding, with the one the world uses marked (frame_compressor.cpp).
#pragma once

#include <string>

namespace beft::bench {

// Renders `ticks` ticks of the scenario, the robot driving and turning, then
// prints the table.
void printPackingTable(const std::string& scenario_path, int ticks);

}  // namespace beft::bench
