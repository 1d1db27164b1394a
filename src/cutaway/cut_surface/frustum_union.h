#pragma once
// The paper's stage 1: one frustum per primary cell, united by an inverted depth test.
#include "cutaway/cut_surface/cut_surface_strategy.h"

namespace cutaway::pipeline {

CutSurfaceEntry frustum_union_entry();
/// One frustum per cluster of adjacent primaries (frustum_clusters.cpp).
CutSurfaceEntry frustum_clusters_entry();

}  // namespace cutaway::pipeline
