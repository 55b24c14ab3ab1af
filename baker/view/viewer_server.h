// The browser viewer's HTTP server (`skybake view`): serves, on 127.0.0.1
// only, the viewer's page (baker/view/page/, compiled in) and one bake's
// web export (baker/export/web_export.h) from memory, and nothing else: a
// path that is not one of those files is 404, whatever it names on disk.
// cpp-httplib does the HTTP.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "baker/export/web_export.h"

namespace skybake {

// Where the export's files are served: /bake/<name>.
inline constexpr const char* kViewerBakePrefix = "/bake/";
// The host the viewer listens on: this machine only.
inline constexpr const char* kViewerHost = "127.0.0.1";

class ViewerServer {
 public:
  ViewerServer();
  ~ViewerServer();
  ViewerServer(const ViewerServer&) = delete;
  ViewerServer& operator=(const ViewerServer&) = delete;

  // Binds kViewerHost:port (0: any free port) and returns the port, or
  // throws Error(BadInput) saying why it cannot (in use, not allowed):
  // first, so that a port that cannot serve is refused before the bake is
  // read.
  int bind(int port);
  // Serves the page and `bake_export` until stop() (from another thread)
  // or a failure.
  void serve(std::vector<WebFile> bake_export);
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace skybake
