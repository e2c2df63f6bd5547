// The help layout of the facet program (see help_format.hpp).
#include "help_format.hpp"

#include <algorithm>
#include <sstream>

namespace facet::cli {

std::string first_sentence(const std::string& description) {
  std::size_t end = std::min(description.find(". "), description.find('\n'));
  return description.substr(0, end);
}

std::string HelpFormat::make_subcommand(const CLI::App* command) const {
  std::stringstream out;
  CLI::detail::format_help(out, command->get_display_name(),
                           first_sentence(command->get_description()), column_width_);
  return out.str();
}

}  // namespace facet::cli
