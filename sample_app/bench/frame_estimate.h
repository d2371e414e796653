#pragma once
// The cost model's estimate of a preset's frame, pass by pass (docs/gpu_cost.md): what bench
// --work prints step by step, summed per pass for the report's rows. Needs the session's GL
// context current and cost::requestMesaShaderDump() called before it was made (without the
// dump the shading term counts invocations only).
#include <array>
#include <string>

#include <gpu_cost.h>
#include <postfx/diagnostics.h>

#include "headless_session.h"
#include "options.h"

namespace ocean {

// Renders `frames` frames with time running, then, the GPU drained, one more: its dispatch reads
// back every query still pending (the plugin's ring never waits).
bool renderFrames(HeadlessSession& session, const Options& options, int frames, std::string& error);

// The plugin's context for `options` with the account kept as `mode`, made the renderer's.
bool usePlugin(HeadlessSession& session, Options options, Options::WorkAccount mode, bool floor,
               std::string& error);

// Each pass's estimated ms on `gpu` with the frame's per-pixel steps at `toPixels` (e.g.
// 1920 x 1080; cost::atViewSize), `options`' frame rendered twice more: once for the programs'
// arithmetic, once with the work counted in the shaders. The session's plugin is then a plain
// one of `options` (with the floor pass where `floor`).
bool estimatePasses(HeadlessSession& session, const Options& options, const cost::GpuClass& gpu,
                    double toPixels, bool floor, std::array<double, postfx::kPassCount>& out,
                    std::string& error);

}  // namespace ocean
