// map.png: the run seen from above. The final obstacle map as the robot saw it
// (unknown / free / occupied), ground-truth objects coloured by category with
// their ids, moving objects' trails, the robot's path, the hypotheses with
// their confidence and state, a metre grid, a scale bar and a legend.
#pragma once

#include <opencv2/core.hpp>

#include "lib/report/run_record.hpp"
#include "lib/report/run_scoring.hpp"

namespace beft::report {

// Where the world lands in the picture: x to the right, y up.
struct MapLayout {
  double scale = 1;     // [px/m]
  int left = 0, top = 0;  // pixel of world (0, world_height)
  int world_px_width = 0, world_px_height = 0;
  int width = 0, height = 0;  // whole picture [px]

  cv::Point toPixel(double x, double y) const;
};

// At most about 1000 x 760 px of world, plus margins and the legend panel.
MapLayout mapLayout(double world_width, double world_height);

cv::Mat renderMap(const RunRecord& record, const RunReport& report);

}  // namespace beft::report
