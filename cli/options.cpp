// Shared options and the words of command-line errors (see options.h).
#include "cli/options.h"

#include <fmt/core.h>
#include <charconv>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cli/scene_error.h"
#include "cli/scene_reader.h"

namespace raintrace::cli {
namespace {

std::string single_quoted(std::string_view text) { return "'" + escaped(text) + "'"; }

/// " (did you mean 'x'?)" when one of `candidates` is a likely typo of `name`, else "".
std::string suggestion(std::string_view name, const std::vector<std::string>& candidates) {
  const auto guess = closest_name(name, candidates);
  return guess ? fmt::format(" (did you mean {}?)", single_quoted(*guess)) : "";
}

/// Every name of every option of `command`: "--seed", "-o", "--output", …
std::vector<std::string> option_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& n : option->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : option->get_snames()) names.push_back("-" + n);
  }
  return names;
}

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    names.push_back(sub->get_name());
  }
  return names;
}

}  // namespace

std::uint64_t parse_seed(std::string_view text) {
  std::uint64_t seed = 0;
  const char* end = text.data() + text.size();
  // from_chars refuses a sign, so "-1" cannot wrap around to 2^64 - 1.
  const auto [stop, error] = std::from_chars(text.data(), end, seed);
  if (text.empty() || error != std::errc{} || stop != end) {
    throw std::invalid_argument(fmt::format(
        "expected a whole number in [0, 18446744073709551615], got {}", single_quoted(text)));
  }
  return seed;
}

CLI::Option* add_seed_option(CLI::App& command, std::optional<std::uint64_t>& seed) {
  return command
      .add_option_function<std::string>(
          "--seed",
          [&seed](const std::string& text) {
            try {
              seed = parse_seed(text);
            } catch (const std::invalid_argument& e) {
              throw CLI::ValidationError("--seed", e.what());
            }
          },
          "Seed of every random stream, overriding the scene file's (same seed: same rain)")
      ->type_name("N");
}

CLI::Validator whole_number_in(int min, int max) {
  return CLI::Validator(
      [min, max](std::string& text) -> std::string {
        int value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc{} || stop != end || value < min || value > max) {
          return fmt::format("must be a whole number in [{}, {}], got {}", min, max,
                             single_quoted(text));
        }
        return {};
      },
      fmt::format("[{}, {}]", min, max));
}

/// A check that a number option's text is a number in `range`, described by `words`.
/// A check that a number option's text is a number in `range`; `bounds` name it in --help.
CLI::Validator number_check(sim::Range range, std::string bounds) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        double value = 0.0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (text.empty() || error != std::errc{} || stop != end || !range.contains(value)) {
          return fmt::format("must be a number {}, got {}", range.describe(), single_quoted(text));
        }
        return {};
      },
      std::move(bounds));
}

CLI::Validator not_negative() { return number_check(sim::Range::at_least(0.0), ">= 0"); }

CLI::Validator positive_number() {
  const sim::Range positive{0.0, std::numeric_limits<double>::infinity(), true, false};
  return number_check(positive, "> 0");
}

CLI::Validator number_in(double min, double max) {
  return number_check(sim::Range::closed(min, max), fmt::format("[{}, {}]", min, max));
}

CLI::Validator one_of(std::initializer_list<std::string_view> choices) {
  std::vector<std::string> names(choices.begin(), choices.end());
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return CLI::Validator(
      [names, list](std::string& text) -> std::string {
        for (const std::string& name : names) {
          if (text == name) return {};
        }
        return fmt::format("expected one of {}, got {}{}", list, single_quoted(text),
                           suggestion(text, names));
      },
      "{" + list + "}");
}

std::string option_error_text(const CLI::App& app, const CLI::ParseError& error) {
  // The command being parsed when the error came: the last subcommand selected, if any.
  const CLI::App* command = &app;
  for (const CLI::App* sub : app.get_subcommands()) command = sub;
  const bool top = command == &app;
  const std::string name = top ? "" : command->get_name();
  const std::string see = top ? "raintrace --help" : "raintrace " + name + " --help";

  std::string what = error.what();
  const std::vector<std::string> extras = app.remaining(true);
  const std::string first = extras.empty() ? "" : extras.front();
  const bool extra_error = dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr;
  // Without a command CLI11 reports a missing command before an unknown word: name the word.
  if (extra_error || (top && dynamic_cast<const CLI::RequiredError*>(&error) != nullptr)) {
    if (!first.empty() && first.front() == '-') {
      const std::string option = first.substr(0, first.find('='));
      what = "unknown option " + single_quoted(option) + suggestion(option, option_names(*command));
    } else if (top && !first.empty()) {
      what = "unknown command " + single_quoted(first) + suggestion(first, command_names(app));
    } else if (top) {
      std::string list;
      for (const std::string& command_name : command_names(app)) {
        list += (list.empty() ? "" : ", ") + command_name;
      }
      what = "a command is required (" + list + ")";
    } else {
      what = "unexpected argument " + single_quoted(first);
    }
  } else if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    // "--seed: 1 required N missing" and the like: the option was given without its value.
    what = what.substr(0, what.find(':')) + ": needs a value";
  }
  return (top ? "" : name + ": ") + what + "; see '" + see + "'";
}

}  // namespace raintrace::cli
