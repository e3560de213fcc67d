// The rain world: drops, splashes and lightning advanced in fixed substeps.
// Contract the rest of raintrace relies on (sim/ may add to it, not change it):
//   World world(params);                 // throws std::invalid_argument naming the bad field
//   world.advance_to(frame_time_s);      // whole substeps; prewarm happens before t = 0
//   Frame frame = world.snapshot(index); // copy of the state for the exporter
// Implementation: see world.cpp (sim helper owns the details).
#pragma once

#include "sim/frame.h"
#include "sim/params.h"
