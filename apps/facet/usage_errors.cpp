// Parse errors in facet's words (see usage_errors.hpp).
#include "usage_errors.hpp"

#include <CLI/CLI.hpp>
#include <cctype>
#include <vector>

namespace facet::cli {
namespace {

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// An argument that is an option name (not a negative number such as -1,0,0 or a lone "-").
bool looks_like_option(const std::string& arg) {
  if (arg.size() < 2 || arg[0] != '-') return false;
  char next = arg[1] == '-' ? (arg.size() > 2 ? arg[2] : '\0') : arg[1];
  return std::isalpha(static_cast<unsigned char>(next)) != 0;
}

// The subcommand named on the command line, or null (none, or a word that is not one).
const CLI::App* command_of(const CLI::App& app, int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (looks_like_option(arg)) continue;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
      if (sub->check_name(arg)) return sub;
    }
    return nullptr;
  }
  return nullptr;
}

// The first word that looks like an option and is none of the program's (before the command)
// or the command's (after it: commands do not take the program's options), skipping the value
// of an option that takes one. CLI11 reports a missing required option before an unknown one,
// which would blame the wrong flag.
struct Unknown {
  std::string name;                 // empty: none
  const CLI::App* owner = nullptr;  // the program or the command it was given to
};

Unknown unknown_option(const CLI::App& app, const CLI::App* command, int argc,
                       const char* const* argv) {
  const CLI::App* owner = &app;  // whose options the next word may be
  bool value_next = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--") break;
    if (value_next) {
      value_next = false;
      continue;
    }
    if (!looks_like_option(arg)) {
      if (owner == &app && command && command->check_name(arg)) owner = command;
      continue;
    }
    // --name=value, -ovalue: the name alone.
    std::string name = arg[1] == '-' ? arg.substr(0, arg.find('=')) : arg.substr(0, 2);
    const CLI::Option* option = owner->get_option_no_throw(name);
    if (!option) return {name, owner};
    value_next = option->get_expected_min() > 0 && name == arg;
  }
  return {};
}

// The text after "NAME: " in a CLI11 message that starts with a flag's name, and the name.
bool split_flag(const std::string& message, std::string& flag, std::string& rest) {
  std::size_t colon = message.find(": ");
  if (colon == std::string::npos || !starts_with(message, "-")) return false;
  flag = message.substr(0, colon);
  rest = message.substr(colon + 2);
  return true;
}

std::string words_for(const CLI::ParseError& error, const CLI::App& app, const CLI::App* command) {
  const std::string message = error.what();
  std::string flag, rest;
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    std::size_t colon = message.find(": ");
    std::string extra = colon == std::string::npos ? message : message.substr(colon + 2);
    if (!command) return "unknown command '" + extra + "'";
    return "unexpected argument '" + extra + "'" +
           (command->get_name() == "render" ? "" : " (this command takes one model)");
  }
  if (dynamic_cast<const CLI::RequiredError*>(&error)) {
    if (starts_with(message, "A subcommand")) {
      return "give a command: render, thumbnail, view, info or bench";
    }
    std::string name = message.substr(0, message.find(" is required"));
    if (name == "--output") return "-o/--output is required: the file to write";
    return name + " is required";
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) && split_flag(message, flag, rest)) {
    if (rest.find("missing") != std::string::npos) return flag + " needs a value";
    if (starts_with(rest, "At Most")) return flag + " takes one value, given more than once";
    return flag + ": wrong number of values";
  }
  if (dynamic_cast<const CLI::ConversionError*>(&error)) {
    if (split_flag(message, flag, rest) && rest.find("flag") != std::string::npos) {
      return flag + " is a switch and takes no value";
    }
    // "Could not convert: --threads = many"
    const std::string prefix = "Could not convert: ";
    if (starts_with(message, prefix)) {
      std::string body = message.substr(prefix.size());
      std::size_t equals = body.find(" = ");
      if (equals != std::string::npos) {
        std::string name = body.substr(0, equals);
        const CLI::App& owner = command ? *command : app;
        const CLI::Option* option = owner.get_option_no_throw(name);
        if (option && option->get_expected_max() == 0) {
          return name + " is a switch and takes no value";
        }
        return name + ": '" + body.substr(equals + 3) + "' is not a number";
      }
    }
  }
  if (dynamic_cast<const CLI::ValidationError*>(&error) && split_flag(message, flag, rest)) {
    return flag + ": '" + rest + "' is not a valid value";
  }
  return message;  // a kind facet's commands do not raise; CLI11's words are all there is
}

}  // namespace

std::string usage_message(const CLI::ParseError& error, const CLI::App& app, int argc,
                          const char* const* argv) {
  const CLI::App* command = command_of(app, argc, argv);
  const CLI::App* help_of = command;  // whose --help to read: null for the program's
  std::string words;
  if (!command && argc > 1 && !looks_like_option(argv[1])) {
    words = "unknown command '" + std::string(argv[1]) + "'";
  } else if (Unknown unknown = unknown_option(app, command, argc, argv); !unknown.name.empty()) {
    words = "unknown option " + unknown.name;
    help_of = unknown.owner == &app ? nullptr : command;
  } else {
    words = words_for(error, app, command);
  }
  return words + " (see facet " + (help_of ? help_of->get_name() + " " : "") + "--help)";
}

}  // namespace facet::cli
