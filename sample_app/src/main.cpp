// ocean_sample: the host application that shows and measures the postfx plugin.
#include <cstdio>

#include "commands.h"
#include "options.h"

int main(int argc, char** argv) {
  ocean::Options options;
  std::string error;
  if (!ocean::parseOptions(argc, argv, options, error)) {
    std::fprintf(stderr, "ocean_sample: %s\n", error.c_str());
    return 2;
  }
  switch (options.command) {
    case ocean::Command::Help:
      std::fputs(ocean::usage().c_str(), stdout);
      return 0;
    case ocean::Command::Render:
      return ocean::runRender(options);
    case ocean::Command::View:
      return ocean::runView(options);
    case ocean::Command::Bench:
      return ocean::runBench(options);
    case ocean::Command::Report:
      return ocean::runReport(options);
    case ocean::Command::Reference:
      return ocean::runReference(options);
    case ocean::Command::Compare:
      return ocean::runCompare(options);
  }
  return 2;
}
