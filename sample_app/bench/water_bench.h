#pragma once
// Cost of the water module: GPU time of Ocean::update() per frame at each resolution, measured
// with GL_TIMESTAMP query pairs, and the GPU memory the ocean holds. Needs a current GL 4.5
// context. Writes a table to `out`; returns 0 on success, 1 when an ocean could not be created
// (the reason is written to `out`).
#include <ostream>

int runWaterBench(std::ostream& out, int frames);
