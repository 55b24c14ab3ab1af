// skybake view FILE.exr [--port N] [--no-open]: the bake's sky in a web
// browser, drawn by the GLSL library in WebGL2 (baker/view/; README.md,
// "Look at a bake").
#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>

#include <csignal>
#include <cstdio>
#include <thread>

#include <fmt/format.h>

#include "baker/cli/bake_web_export.h"
#include "baker/cli/commands.h"
#include "baker/view/viewer_server.h"

extern char** environ;

namespace skybake::cli {
namespace {

// The default port: above the registered ones, rarely taken.
constexpr int kDefaultViewerPort = 8765;
constexpr int kMaxPort = 65535;

struct ViewOptions {
  std::string bake_path;
  int port = kDefaultViewerPort;
  bool no_open = false;
};

// Asks the desktop to open `url` (xdg-open, without waiting for it); false
// where there is no xdg-open or it cannot start.
bool openInBrowser(const std::string& url) {
  pid_t pid = 0;
  std::string program = "xdg-open";
  std::vector<char*> argv = {program.data(), const_cast<char*>(url.c_str()), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  // Its chatter (a browser's warnings) would interleave with ours.
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  const int status = posix_spawnp(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return status == 0;
}

void runView(const ViewOptions& o) {
  // Ctrl-C and SIGTERM stop the server from a thread of their own: blocked
  // in every thread (all start after this: the export's OpenMP workers and
  // the server's), taken by sigwait.
  // Blocked first, then given a handler of their own: a signal ignored
  // where it was inherited so (a shell's background job ignores SIGINT)
  // would never be pending, and one arriving between the two steps in the
  // other order would run the handler and be lost.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  struct sigaction take {};
  take.sa_handler = [](int) {};
  sigaction(SIGINT, &take, nullptr);
  sigaction(SIGTERM, &take, nullptr);
  // SIGPIPE: a browser that closes a connection mid-file must not end us.
  std::signal(SIGPIPE, SIG_IGN);

  ViewerServer server;
  const int port = server.bind(o.port);
  // The tables as they are: the page is on this machine, where gzip would
  // cost the server its compression and the page its unpacking.
  std::vector<WebFile> files = webExportOfBakeFile(o.bake_path, WebTableEncoding::None).files;
  const std::string url = fmt::format("http://{}:{}/", kViewerHost, port);
  fmt::print("skybake view: {} at {} (Ctrl-C stops)\n", o.bake_path, url);
  if (!o.no_open && !openInBrowser(url)) fmt::print("skybake view: no xdg-open here: open {} in a browser\n", url);
  std::fflush(stdout);

  std::thread stopper([&] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    server.stop();
  });
  server.serve(std::move(files));
  // Served to the end without a signal (the server failed): wake the
  // stopper with one of its own signals.
  pthread_kill(stopper.native_handle(), SIGTERM);
  stopper.join();
  fmt::print("skybake view: stopped\n");
}

}  // namespace

Command addViewCommand(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Look at a bake in a web browser: serves, on 127.0.0.1 only, a page that draws its sky with the GLSL library "
      "in WebGL2 (camera altitude, sun, view, exposure, a moon for eclipses, radiance under the cursor).");
  cmd->add_option("file", o->bake_path, "Bake file (.exr).")->required();
  cmd->add_option("--port", o->port, "TCP port on 127.0.0.1 (0: any free port).")
      ->check(CLI::Range(0, kMaxPort))
      ->capture_default_str();
  cmd->add_flag("--no-open", o->no_open, "Print the page's address without asking the desktop to open it.");
  return {cmd, [o] { runView(*o); }};
}

}  // namespace skybake::cli
