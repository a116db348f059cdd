// weights.png: the paper's Fig. 4. Every acoustic object's dynamic weight
// (eq. 4) over simulated time, one coloured line each, with the congruency
// levels 0.25 / 0.5 / 0.75 dashed and the turn-to reflexes marked; below it a
// strip with the task on top of the stack over time, and a small plot of the
// viewing direction (as DW commands it, and the head's actual heading).
#pragma once

#include <opencv2/core.hpp>

#include "lib/report/run_record.hpp"

namespace beft::report {

inline constexpr int kWeightsPictureWidth = 1280;
inline constexpr int kWeightsPictureHeight = 880;

cv::Mat renderWeights(const RunRecord& record);

}  // namespace beft::report
