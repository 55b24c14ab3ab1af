// skybake: the command line. Only this layer prints errors and picks exit
// statuses: 0 success, 2 bad input (config, flags, files), 1 internal failure.
#include <cstdio>
#include <exception>
#include <vector>

#include <fmt/format.h>

#include "baker/cli/commands.h"
#include "data_formats/error.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"skybake: bakes physically based sky scattering tables (Bruneton-style) into one "
               "OpenEXR file."};
  app.require_subcommand(1);
  const std::vector<skybake::cli::Command> commands = {
      skybake::cli::addBakeCommand(app),
      skybake::cli::addInfoCommand(app),
      skybake::cli::addLookupCommand(app),
      skybake::cli::addRenderCommand(app),
      skybake::cli::addValidateCommand(app),
      skybake::cli::addCompareCommand(app),
      skybake::cli::addStressCommand(app),
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  }
  try {
    for (const skybake::cli::Command& command : commands) {
      if (command.subcommand->parsed()) command.run();
    }
  } catch (const skybake::Error& e) {
    fmt::print(stderr, "skybake: error: {}\n", e.what());
    return e.kind() == skybake::ErrorKind::BadInput ? kExitBadInput : kExitInternal;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "skybake: error: out of memory\n");
    return kExitInternal;
  } catch (const std::exception& e) {
    fmt::print(stderr, "skybake: internal error: {}\n", e.what());
    return kExitInternal;
  }
  return 0;
}
