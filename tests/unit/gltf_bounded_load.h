#pragma once
// A glTF load in a child process, timed and measured: its peak resident memory (the child's
// own, so what earlier tests held does not hide it) and whether it finished before a deadline
// (a file that hangs the loader fails the test instead of hanging it; a file that would take
// gigabytes meets an address-space cap first).

#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "scene/gltf_loader.h"

namespace gltf_bounded_load {

struct Outcome {
  bool finished = false;  // the child exited before the deadline
  bool loaded = false;
  std::string error;     // loadGlb's message when refused
  double seconds = 0.0;  // until it exited or was killed
  double peakMb = 0.0;   // the child's peak resident memory, MB
};

// Loads `path` with `limits` in a child that is killed after `deadlineSeconds` and whose
// address space is capped at 8 GB (so an unbounded file fails there rather than swapping).
inline Outcome load(const std::string& path, double deadlineSeconds,
                    const ocean_scene::GltfLimits& limits = {}) {
  Outcome o;
  int channel[2];
  if (pipe(channel) != 0) return o;
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = fork();
  if (child == 0) {
    close(channel[0]);
    const rlimit cap{std::uint64_t(8) << 30, std::uint64_t(8) << 30};
    setrlimit(RLIMIT_AS, &cap);
    ocean_scene::Model model;
    std::string error;
    const bool loaded = ocean_scene::loadGlb(path, model, error, nullptr, limits);
    const std::string said = (loaded ? "1" : "0") + error;
    ssize_t written = write(channel[1], said.data(), said.size());
    (void)written;
    _exit(0);
  }
  close(channel[1]);
  int status = 0;
  rusage usage{};
  for (;;) {
    const pid_t done = wait4(child, &status, WNOHANG, &usage);
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == child) {
      o.finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      break;
    }
    if (o.seconds > deadlineSeconds) {
      kill(child, SIGKILL);
      wait4(child, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  o.peakMb = double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
  std::string said;
  char buffer[4096];
  for (ssize_t n; (n = read(channel[0], buffer, sizeof buffer)) > 0;) said.append(buffer, n);
  close(channel[0]);
  o.loaded = o.finished && !said.empty() && said[0] == '1';
  o.error = said.empty() ? std::string() : said.substr(1);
  return o;
}

}  // namespace gltf_bounded_load
