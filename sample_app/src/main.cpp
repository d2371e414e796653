// ocean_sample: the host application that shows and measures the postfx plugin.
#include <cstdio>

#include "commands.h"
#include "options.h"

int main(int argc, char** argv) {
  const ocean::ParsedCommandLine parsed = ocean::parseCommandLine(argc, argv);
  switch (parsed.outcome) {
    case ocean::ParsedCommandLine::Outcome::Error:
      std::fprintf(stderr, "ocean_sample: %s\n", parsed.text.c_str());
      return 2;
    case ocean::ParsedCommandLine::Outcome::Help:
      std::fputs(parsed.text.c_str(), stdout);
      return 0;
    case ocean::ParsedCommandLine::Outcome::Run:
      break;
  }
  const ocean::Options& options = parsed.options;
  switch (options.command) {
    case ocean::Command::Help:
      return 2;  // not produced by the parser: help is an outcome above
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
