// The command line's parse errors in facet's words: CLI11's messages ("At Most 1 required but
// received 2", "The following argument was not expected") become one line naming the flag or
// word at fault and the --help of the command it was given to.
#pragma once

#include <string>

#include "cli_fwd.hpp"

namespace facet::cli {

// The line to print after "facet: error: " for a parse error of `app` on argv.
std::string usage_message(const CLI::ParseError& error, const CLI::App& app, int argc,
                          const char* const* argv);

}  // namespace facet::cli
