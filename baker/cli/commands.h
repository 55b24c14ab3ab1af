// The skybake subcommands. Each registers its options on the CLI11 app and
// returns the function that runs it; errors are thrown as skybake::Error.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace skybake::cli {

struct Command {
  CLI::App* subcommand;       // parsed() tells whether the user chose it
  std::function<void()> run;  // runs it with the parsed options
};

Command addBakeCommand(CLI::App& app);
Command addInfoCommand(CLI::App& app);
Command addLookupCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addValidateCommand(CLI::App& app);
Command addReferenceCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addStressCommand(CLI::App& app);
Command addExportCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);

}  // namespace skybake::cli
