// Command-line options shared by the subcommands, and the words of command-line errors. Every
// option error is one line, "raintrace: error: COMMAND: OPTION: what is wrong", with a "did you
// mean" when a name or value is close to a known one, and where to look for the options.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace raintrace::cli {

/// `--seed N`: the seed of every random stream, overriding the scene file's, a whole number in
/// [0, 2^64 − 1]. The same option, with the same words, on every command that simulates
/// (simulate, export, render).
CLI::Option* add_seed_option(CLI::App& command, std::optional<std::uint64_t>& seed);

/// Parses a seed as add_seed_option does. Throws std::invalid_argument with the option's words.
std::uint64_t parse_seed(std::string_view text);

/// A check that an integer option lies in [min, max]: "must be a whole number in [1, 256], got
/// '0'".
CLI::Validator whole_number_in(int min, int max);

/// A check that a number option is >= 0: "must be a number >= 0, got '-1'".
CLI::Validator not_negative();

/// A check that a number option is > 0: "must be a number > 0, got '-1'".
CLI::Validator positive_number();

/// A check that a number option lies in [min, max]: "must be a number in [0, 100], got '150'".
CLI::Validator number_in(double min, double max);

/// A check that a text option is one of `choices`: "expected one of preview, final, got
/// 'finale' (did you mean 'final'?)".
CLI::Validator one_of(std::initializer_list<std::string_view> choices);

/// The one line raintrace prints (after "raintrace: error: ") for a parse error of `app`, e.g.
/// "simulate: unknown option '--seeed' (did you mean '--seed'?); see 'raintrace simulate
/// --help'". Not for --help and --version, which are no errors.
std::string option_error_text(const CLI::App& app, const CLI::ParseError& error);

}  // namespace raintrace::cli
