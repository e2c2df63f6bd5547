// The geometry stage as a whole: vertex transform (vertex.cpp) for every draw, then primitive
// assembly, clipping and setup (primitive.cpp) in parallel chunks of primitives, merged in
// submission order into the frame's primitive buffer for binning.
#pragma once

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Runs on the caller's task arena with `workers` threads. The result does not depend on
// the thread count: chunks are fixed-size and merged in order.
void run_geometry(Frame& frame, int workers);

}  // namespace facet::pipeline
