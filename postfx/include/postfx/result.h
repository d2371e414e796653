#pragma once
// Result codes returned by every postfx entry point. On anything but Ok, lastError() holds a
// sentence naming the offending field and value, and nothing was drawn or changed.
namespace postfx {

enum class Result {
  Ok = 0,
  InvalidArgument,      // a value out of its documented range, NaN/Inf, or a bad enum
  MissingTexture,       // a required texture is 0 or not a texture name
  UnsupportedFormat,    // a texture's internal format or target is not one this input accepts
  SizeMismatch,         // textures that must match in size do not
  ShaderCompileFailed,  // create() could not build a program; the message has the driver log
  GlError,              // the driver refused a GL object (framebuffer incomplete, ...)
  OutOfMemory,          // the frame needs more GPU memory than CreateDesc::memoryBudgetMiB
                        // (refused before anything is allocated), or an allocation failed
  NoContext,            // no GL context is current on the calling thread
};

// Stable English name of the code, e.g. "UnsupportedFormat".
const char* toString(Result result) noexcept;

}  // namespace postfx
