// The geometry stage as a whole: vertex transform (vertex.cpp) for every draw, then primitive
// assembly, clipping and setup (primitive.cpp) in parallel chunks of primitives, each writing
// into its own regions of the frame's primitive arrays (primitive_sink.hpp); binning walks the
// chunks' sequences in order.
#pragma once

#include "pipeline/frame.hpp"

namespace facet::pipeline {

// Runs on the caller's task arena with `workers` threads. The result does not depend on
// the thread count: chunks and their regions are fixed by the draws alone.
void run_geometry(Frame& frame, int workers);

}  // namespace facet::pipeline
