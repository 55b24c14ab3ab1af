#include "baker/cli/option_checks.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake::cli {
namespace {

// The number `text` spells exactly (no trailing characters), finite or not.
std::optional<double> parseNumber(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

// Adds a check that refuses with `reason` unless `accepts(value text)`.
template <typename Accepts>
CLI::Option* addCheck(CLI::Option* option, std::string description, std::string reason, Accepts accepts) {
  const std::string name = option->get_name();
  option->check(CLI::Validator(
      [name, reason, accepts](std::string& text) -> std::string {
        if (!accepts(text)) refuseOptionValue(name, text, reason);
        return {};
      },
      std::move(description)));
  return option;
}

}  // namespace

void refuseOptionValue(const std::string& option, const std::string& value, const std::string& reason) {
  throwBadInput(fmt::format("{} = {}: {}", option, value, reason));
}

std::array<double, 2> parseRangeOption(const std::string& option, const std::string& text) {
  const size_t colon = text.find(':');
  const std::optional<double> low = colon == std::string::npos ? std::nullopt : parseNumber(text.substr(0, colon));
  const std::optional<double> high = colon == std::string::npos ? std::nullopt : parseNumber(text.substr(colon + 1));
  if (!low || !high || !std::isfinite(*low) || !std::isfinite(*high)) {
    refuseOptionValue(option, text, "must be LOW:HIGH, two finite numbers");
  }
  return {*low, *high};
}

std::optional<long long> parseWholeNumber(const std::string& text) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

void refuseEmptyOptionValues(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0 || option->get_expected_min() == 0) continue;  // not given, or a flag
    for (const std::string& value : option->results()) {
      if (value.empty()) {
        const std::string name =
            option->get_lnames().empty() ? option->get_name() : "--" + option->get_lnames().front();
        refuseOptionValue(name, "\"\"", "an empty value: give one, or leave the option out");
      }
    }
  }
}

void requireOrdersChoice(const std::string& option, const std::string& text) {
  if (text == "auto") return;
  const std::optional<long long> count = parseWholeNumber(text);
  if (!count || *count < 1 || *count > kMaxOrders) {
    refuseOptionValue(option, text, fmt::format("must be 'auto' or a whole number in [1, {}]", kMaxOrders));
  }
}

void applyOrdersChoice(const std::string& option, const std::string& text, BakeConfig& config) {
  requireOrdersChoice(option, text);
  config.bake.auto_orders = text == "auto";
  if (!config.bake.auto_orders) config.bake.orders = static_cast<int>(*parseWholeNumber(text));
}

CLI::Option* requireFiniteIn(CLI::Option* option, double lowest, double highest) {
  return addCheck(option, fmt::format("finite number in [{:g}, {:g}]", lowest, highest),
                  fmt::format("must be a finite number in [{:g}, {:g}]", lowest, highest),
                  [lowest, highest](const std::string& text) {
                    const std::optional<double> v = parseNumber(text);
                    return v && std::isfinite(*v) && *v >= lowest && *v <= highest;
                  });
}

CLI::Option* requirePositiveUpTo(CLI::Option* option, double highest) {
  return addCheck(option, fmt::format("finite number in (0, {:g}]", highest),
                  fmt::format("must be a finite number in (0, {:g}]", highest), [highest](const std::string& text) {
                    const std::optional<double> v = parseNumber(text);
                    return v && std::isfinite(*v) && *v > 0.0 && *v <= highest;
                  });
}

CLI::Option* requireWholeIn(CLI::Option* option, long long lowest, long long highest) {
  return addCheck(option, fmt::format("whole number in [{}, {}]", lowest, highest),
                  fmt::format("must be a whole number in [{}, {}]", lowest, highest),
                  [lowest, highest](const std::string& text) {
                    const std::optional<long long> v = parseWholeNumber(text);
                    return v && *v >= lowest && *v <= highest;
                  });
}

CLI::Option* addThreadsOption(CLI::App& command, int& threads) {
  return requireWholeIn(command.add_option("--threads", threads, "Worker threads (default: all cores)."), 1,
                        kMaxThreadCount);
}

}  // namespace skybake::cli
