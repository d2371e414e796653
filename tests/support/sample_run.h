#pragma once
// Runs the ocean_sample executable (OCEAN_SAMPLE_EXE) with arguments, for the tests of its
// command line: exit code, standard error and output, each written to a scratch folder first.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace testsupport {

struct SampleRun {
  int exitCode = -1;
  std::string err, out;
};

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline SampleRun runSample(const std::string& executable, const std::string& arguments,
                           const std::filesystem::path& scratch) {
  const std::filesystem::path err = scratch / "stderr.txt", out = scratch / "stdout.txt";
  const std::string command =
      executable + " " + arguments + " 2>" + err.string() + " >" + out.string();
  const int status = std::system(command.c_str());
  SampleRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = slurp(err);
  run.out = slurp(out);
  return run;
}

}  // namespace testsupport
