// skybake: the command line. Only this layer prints errors and picks exit
// statuses: 0 success, 2 bad input (config, flags, files, output locations),
// 1 internal failure.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "baker/cli/commands.h"
#include "baker/cli/option_checks.h"
#include "data_formats/bake_file/bake_file.h"
#include "data_formats/error.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

// CLI11's own parse errors (unknown subcommand, missing required option) in
// skybake's form, with its pointer to --help.
std::string cliFailureMessage(const CLI::App*, const CLI::Error& e) {
  return fmt::format("skybake: error: {}\nRun with --help for more information.\n", e.what());
}

// Prints the final error line without throwing: fmt::print throws when
// stderr itself cannot be written (a file on the full disk being reported).
void printError(const std::string& message) {
  std::fputs(message.c_str(), stderr);
  std::fflush(stderr);
}

// Everything printed to standard output must have arrived: a full disk
// behind a redirection is a failed run, not a silently short table.
bool standardOutputWritten() { return std::fflush(stdout) == 0 && std::ferror(stdout) == 0; }

// Where the documents that --help and messages name (data_formats/CONFIG.md,
// docs/QUERIES.md, ...) are: installed, in the doc folder relative to the
// command's own (SKYBAKE_DOC_DIR, from the install layout); run from its
// build tree, in the source tree it was built from.
std::string documentsFolder() {
  std::error_code error;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path installed = (program.parent_path() / SKYBAKE_DOC_DIR).lexically_normal();
    if (std::filesystem::is_regular_file(installed / "data_formats" / "CONFIG.md", error)) return installed.string();
  }
  return SKYBAKE_SOURCE_DIR;
}

}  // namespace

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) then fails the write with EFBIG, which is
  // reported and cleaned up like a full disk, instead of killing skybake with
  // its temporary file left behind.
  std::signal(SIGXFSZ, SIG_IGN);

  CLI::App app{
      "skybake: bakes physically based sky scattering tables (Bruneton-style) into one "
      "OpenEXR file."};
  app.footer(
      fmt::format("Documents named here and in messages (data_formats/CONFIG.md, docs/QUERIES.md, ...) are "
                  "in {}.",
                  documentsFolder()));
  app.failure_message(cliFailureMessage);  // before the subcommands, which copy it
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("skybake {} (writes bake file format {}, reads formats {} to {})",
                                                SKYBAKE_VERSION, skybake::kBakeFormatVersion,
                                                skybake::kOldestReadBakeFormatVersion, skybake::kBakeFormatVersion));
  const std::vector<skybake::cli::Command> commands = {
      skybake::cli::addBakeCommand(app),   skybake::cli::addInfoCommand(app),      skybake::cli::addLookupCommand(app),
      skybake::cli::addRenderCommand(app), skybake::cli::addValidateCommand(app),  skybake::cli::addCompareCommand(app),
      skybake::cli::addStressCommand(app), skybake::cli::addReferenceCommand(app), skybake::cli::addExportCommand(app),
      skybake::cli::addViewCommand(app),
  };

  try {
    // Option checks (baker/cli/option_checks.h) throw skybake::Error from
    // inside the parse; it is handled below like any other input error.
    app.parse(argc, argv);
    for (const skybake::cli::Command& command : commands) {
      if (!command.subcommand->parsed()) continue;
      skybake::cli::refuseEmptyOptionValues(*command.subcommand);
      command.run();
    }
    if (!standardOutputWritten()) {
      throw skybake::Error(skybake::ErrorKind::BadInput,
                           fmt::format("standard output: cannot write: {}", std::strerror(errno)));
    }
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitBadInput;
  } catch (const skybake::Error& e) {
    printError(fmt::format("skybake: error: {}\n", e.what()));
    return e.kind() == skybake::ErrorKind::BadInput ? kExitBadInput : kExitInternal;
  } catch (const std::bad_alloc&) {
    printError("skybake: error: out of memory\n");
    return kExitInternal;
  } catch (const std::exception& e) {
    printError(fmt::format("skybake: internal error: {}\n", e.what()));
    return kExitInternal;
  }
  return 0;
}
