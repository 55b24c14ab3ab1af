// Checks for numeric command-line options, shared by every subcommand.
//
// CLI11's Range lets NaN through (every comparison with NaN is false), prints
// its bounds with six decimals ("0.000000" for 1e-9) and words its own
// message. These checks refuse non-finite and out-of-range values and word
// the refusal like every other skybake input error: "<option> = <value>:
// <reason>", exit status 2. They throw skybake::Error, which CLI11 passes
// through its parse (it catches only its own ValidationError), so the option
// name is not prefixed twice.
#pragma once

#include <array>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "baker/stages/openmp_threads.h"  // kMaxThreadCount
#include "data_formats/config/config.h"

namespace skybake::cli {

// A finite number in [lowest, highest].
CLI::Option* requireFiniteIn(CLI::Option* option, double lowest, double highest);

// A finite number in (0, highest].
CLI::Option* requirePositiveUpTo(CLI::Option* option, double highest);

// A whole number (no sign other than '-', no fraction, no exponent) in
// [lowest, highest].
CLI::Option* requireWholeIn(CLI::Option* option, long long lowest, long long highest);

// The --threads option every parallel subcommand has: a whole number in
// [1, kMaxThreadCount]; `threads` stays 0 (all cores) when it is not given.
CLI::Option* addThreadsOption(CLI::App& command, int& threads);

// "LOW:HIGH", two finite numbers (a range option such as --altitude-range);
// refuses anything else naming `option`.
std::array<double, 2> parseRangeOption(const std::string& option, const std::string& text);

// The whole number `text` spells exactly, or nothing.
std::optional<long long> parseWholeNumber(const std::string& text);

// A choice of scattering orders, "auto" or a whole number in [1, kMaxOrders]
// (the command line's --orders, Python's orders=): refuses others as
// "<option> = <text>: <reason>".
void requireOrdersChoice(const std::string& option, const std::string& text);
// The same, then sets bake.orders or bake.auto_orders of `config`.
void applyOrdersChoice(const std::string& option, const std::string& text, BakeConfig& config);

// Refuses an option or positional of `command` given an empty value
// (`--moon ""`): it would otherwise read as the option left out.
void refuseEmptyOptionValues(const CLI::App& command);

// Throws Error(BadInput) "<option> = <value>: <reason>".
[[noreturn]] void refuseOptionValue(const std::string& option, const std::string& value, const std::string& reason);

}  // namespace skybake::cli
