// How `facet --help` lays out its commands: one line each (the first sentence of the command's
// description), so the program's help fits a screen; `facet COMMAND --help` shows the whole.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace facet::cli {

class HelpFormat : public CLI::Formatter {
 public:
  std::string make_subcommand(const CLI::App* command) const override;
};

// A description's first sentence: up to its first ". " or line break.
std::string first_sentence(const std::string& description);

}  // namespace facet::cli
