// The one table of vkpt's options: each option's names, value, meaning, default, the
// values it accepts and how it sets Options. ParseOptions, --help, the "options" object
// of --stats and the table of docs/options.md (checked by tests/test_options.cpp) all
// come from it; to add an option, add a row to option_table.cpp.
#pragma once

#include <string>
#include <vector>

#include "app/option_values.h"

namespace vkpt::internal {

struct OptionDef {
  std::vector<std::string> names;  // as listed: "-v", "--verbose"
  std::string value;               // its placeholder(s): "FILE", "A B"; empty for a flag
  std::string meaning;             // one line; `code` in backticks (--help drops them)
  std::string defaultText;         // as shown; empty: nothing to show
  OptionValue how;

  size_t Arity() const;          // values taken: the words of `value`
  std::string LongName() const;  // the last name: "--verbose"
  std::string StatsKey() const;  // "max_depth" for --max-depth
  std::string Synopsis() const;  // "-v, --verbose", "--scene FILE"
};

// Every option, in the order --help and the docs list them.
const std::vector<OptionDef>& OptionTable();
const OptionDef* FindOption(const std::string& name);  // by any of its names; null if none

// The table as docs/options.md has it: header, separator and one row per option.
std::string OptionTableMarkdown();
// The options part of --help: each option, its meaning, values and default, wrapped.
std::string OptionHelpLines();

}  // namespace vkpt::internal
