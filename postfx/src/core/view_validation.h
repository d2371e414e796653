#pragma once
// What a multi-view dispatch checks of its list before any GL work, beside each view's frame
// (validation.h): the list, each view's viewport, and views sharing a target.
#include <epoxy/gl.h>

#include <span>
#include <string>

#include <postfx/postfx.h>

#include "core/validation.h"

namespace postfx::detail {

// "views[i]: " before a message about one view's own inputs in a multi-view dispatch (`listed`);
// nothing before one about a field the views share (water, sun, settings), nor for a plain
// dispatch(context, frame). Returns r.
Result prefixed(Result r, std::string& error, int index, bool listed);

// The list itself: its length in [1, kMaxViews], every view non-null, a live view of `context`
// (looked up by address, never dereferenced: a destroyed one is refused) and listed once (a view
// listed twice would advance its god-ray pivot and timers twice).
Result validateViewList(const Context& context, std::span<const ViewDesc> views,
                        std::string& error);

// The view's viewport inside its target (textures as validated, the whole target): on success
// `textures` describes the rectangle the passes work in.
Result applyViewport(const Viewport& viewport, ValidatedTextures& textures, std::string& error);

// A view's rectangle in its target.
struct ViewRect {
  GLuint target = 0;
  ValidatedTextures rect;
};
// Two views adding light into one target must not add it twice to a pixel: their rectangles in
// a shared target must not overlap.
Result checkViewOverlaps(std::span<const ViewRect> views, std::string& error);

}  // namespace postfx::detail
