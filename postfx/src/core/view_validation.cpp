// The checks of a multi-view dispatch's list (see view_validation.h).
#include "core/view_validation.h"

#include "core/context.h"

namespace postfx::detail {

namespace {

// Whether a refusal is about one of the view's own inputs (its G-buffer, target, camera, shadow
// map, viewport, or a constant made from its camera), rather than a frame field every view
// shares: only the former is the view's to fix, so only it names the view.
bool aboutTheView(const std::string& error) {
  for (const char* field :
       {"depth", "normal", "albedo", "target", "camera", "shadow", "viewport", "frame:"})
    if (error.rfind(field, 0) == 0) return true;
  return false;
}

}  // namespace

Result prefixed(Result r, std::string& error, int index, bool listed) {
  if (r != Result::Ok && listed && aboutTheView(error))
    error = "views[" + std::to_string(index) + "]: " + error;
  return r;
}

Result validateViewList(const Context& context, std::span<const ViewDesc> views,
                        std::string& error) {
  if (views.empty() || views.size() > static_cast<std::size_t>(kMaxViews)) {
    error = "viewCount is " + std::to_string(views.size()) + ", must be in [1, " +
            std::to_string(kMaxViews) + "]";
    return Result::InvalidArgument;
  }
  for (std::size_t i = 0; i < views.size(); ++i) {
    const View* v = views[i].view;
    const std::string name = "views[" + std::to_string(i) + "].view";
    if (v == nullptr) {
      error = name + " is null (createView gives one)";
      return Result::InvalidArgument;
    }
    // Found among the context's live views by address, never dereferenced: a destroyed view or
    // another context's is refused, not read.
    bool live = false;
    for (const auto& mine : context.views) live = live || mine.get() == v;
    if (!live) {
      error = name + " is not a live view of this context (createView on it, not destroyed)";
      return Result::InvalidArgument;
    }
    for (std::size_t j = 0; j < i; ++j)
      if (views[j].view == v) {
        error = name + " is listed twice (views[" + std::to_string(j) +
                "] too): its god-ray pivot and timers would advance twice";
        return Result::InvalidArgument;
      }
  }
  return Result::Ok;
}

Result applyViewport(const Viewport& v, ValidatedTextures& textures, std::string& error) {
  if (v.width == 0 && v.height == 0 && v.x == 0 && v.y == 0) return Result::Ok;
  const bool inside = v.x >= 0 && v.y >= 0 && v.width > 0 && v.height > 0 &&
                      v.width <= textures.targetWidth - v.x &&
                      v.height <= textures.targetHeight - v.y;
  if (!inside) {
    error = "viewport (" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " +
            std::to_string(v.width) + " x " + std::to_string(v.height) +
            ") must have a positive size and lie inside the " +
            std::to_string(textures.targetWidth) + " x " + std::to_string(textures.targetHeight) +
            " target (0 x 0 at 0, 0: the whole target)";
    return Result::InvalidArgument;
  }
  textures.x = v.x;
  textures.y = v.y;
  textures.width = v.width;
  textures.height = v.height;
  return Result::Ok;
}

Result checkViewOverlaps(std::span<const ViewRect> views, std::string& error) {
  for (std::size_t i = 0; i < views.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const ValidatedTextures& a = views[i].rect;
      const ValidatedTextures& b = views[j].rect;
      if (views[i].target != views[j].target) continue;
      const bool apart = a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y ||
                         b.y + b.height <= a.y;
      if (!apart) {
        error = "views[" + std::to_string(i) + "] and views[" + std::to_string(j) +
                "] share a target and their viewports overlap (light would be added twice)";
        return Result::InvalidArgument;
      }
    }
  return Result::Ok;
}

}  // namespace postfx::detail
