#pragma once
// Error reporting for the water module: a code the host can branch on plus a message it can
// show. Nothing in this module prints, throws across its API or aborts.

namespace postfx::water {

enum class Result {
  Ok,
  InvalidArgument,      // a field of OceanDesc, or a time value, is out of its documented range
  Unsupported,          // the GL implementation's limits cannot hold the requested resolution
  ShaderCompileFailed,  // an embedded shader failed to compile or link (message has the log)
  GlError,              // the driver reported an error while allocating (e.g. out of memory)
  NoContext,            // no GL context is current on the calling thread
};

inline const char* toString(Result result) {
  switch (result) {
    case Result::Ok:
      return "Ok";
    case Result::InvalidArgument:
      return "InvalidArgument";
    case Result::Unsupported:
      return "Unsupported";
    case Result::ShaderCompileFailed:
      return "ShaderCompileFailed";
    case Result::GlError:
      return "GlError";
    case Result::NoContext:
      return "NoContext";
  }
  return "Unknown";
}

}  // namespace postfx::water
