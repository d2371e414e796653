#include "gltf_stderr.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>

#include "gltf_text.h"

namespace ocean_scene::gltf {

StderrCapture::StderrCapture() {
  std::fflush(stderr);
  captive_ = ::memfd_create("ocean_gltf_stderr", MFD_CLOEXEC);
  if (captive_ < 0) return;
  saved_ = ::dup(2);
  if (saved_ < 0 || ::dup2(captive_, 2) < 0) {
    if (saved_ >= 0) ::close(saved_);
    ::close(captive_);
    saved_ = captive_ = -1;
  }
}

StderrCapture::~StderrCapture() {
  take();
}

std::string StderrCapture::take() {
  if (saved_ < 0) return "";
  std::fflush(stderr);
  ::dup2(saved_, 2);
  ::close(saved_);
  saved_ = -1;
  // Enough for a library's first lines; anything beyond is cut by excerpt() anyway.
  char text[4096];
  const ssize_t got = ::pread(captive_, text, sizeof text, 0);
  const off_t total = got > 0 ? ::lseek(captive_, 0, SEEK_END) : 0;
  ::close(captive_);
  captive_ = -1;
  if (got <= 0) return "";
  const std::string line = safeOneLine(std::string_view(text, std::size_t(got)));
  return excerpt(line, kMaxQuotedChars, total > got ? std::size_t(total) : 0);
}

}  // namespace ocean_scene::gltf
