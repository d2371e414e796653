#pragma once
// Every option of ocean_sample in one table: its name, what it takes, its help line, and the
// check that turns its text into a value in Options (NaN, infinities, out-of-range and
// half-read numbers are refused with one line naming the option). The command line (cli.cpp)
// decides which command offers which option; this file decides what each one means.
#include <span>
#include <string>
#include <string_view>

#include "options.h"

namespace ocean {

struct ValueOption {
  std::string_view flag;      // "--width"
  std::string_view typeName;  // shown in --help: "W"
  std::string_view help;
  bool repeatable;  // --model: one per file; every other option at most once
  // Stores the checked value; false with the one-line refusal in `error`.
  bool (*apply)(std::string_view text, Options& options, std::string& error);
};

struct FlagOption {
  std::string_view flag;
  std::string_view help;
  void (*apply)(Options& options);
};

std::span<const ValueOption> valueOptions();
std::span<const FlagOption> flagOptions();
const ValueOption* findValueOption(std::string_view flag);
const FlagOption* findFlagOption(std::string_view flag);

}  // namespace ocean
