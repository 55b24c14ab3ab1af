#include "baker/view/viewer_server.h"

#include <httplib.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <thread>

#include <fmt/format.h>

#include "baker/view/viewer_page.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

std::string mediaTypeOf(std::string_view name) {
  auto ends = [&](std::string_view suffix) {
    return name.size() >= suffix.size() && name.substr(name.size() - suffix.size()) == suffix;
  };
  if (ends(".html")) return "text/html; charset=utf-8";
  if (ends(".js")) return "text/javascript; charset=utf-8";
  if (ends(".css")) return "text/css; charset=utf-8";
  return "text/plain; charset=utf-8";
}

struct Served {
  std::string_view bytes;
  std::string media_type;
};

}  // namespace

struct ViewerServer::Impl {
  std::atomic<bool> served{false};  // serve() has returned
  std::vector<WebFile> bake_export;
  std::map<std::string, Served, std::less<>> files;  // by request path
  httplib::Server server;
};

ViewerServer::ViewerServer() : impl_(std::make_unique<Impl>()) {
  impl_->server.Get(".*", [this](const httplib::Request& request, httplib::Response& response) {
    const auto it = impl_->files.find(request.path);
    if (it == impl_->files.end()) {
      response.status = 404;
      response.set_content("not a file of this viewer\n", "text/plain; charset=utf-8");
      return;
    }
    const std::string_view bytes = it->second.bytes;
    // The bake is fixed while the server runs; the page may change between
    // runs of different skybake versions.
    response.set_header("Cache-Control", "no-cache");
    response.set_content_provider(bytes.size(), it->second.media_type,
                                  [bytes](size_t offset, size_t length, httplib::DataSink& sink) {
                                    sink.write(bytes.data() + offset, std::min(length, bytes.size() - offset));
                                    return true;
                                  });
  });
}

ViewerServer::~ViewerServer() = default;

int ViewerServer::bind(int port) {
  errno = 0;
  const int bound = port == 0 ? impl_->server.bind_to_any_port(kViewerHost)
                              : (impl_->server.bind_to_port(kViewerHost, port) ? port : -1);
  if (bound <= 0) {
    throwBadInput(fmt::format("--port = {}: cannot listen on {}:{}: {} (choose another port, or 0 for any free one)",
                              port, kViewerHost, port, errno != 0 ? std::strerror(errno) : "refused"));
  }
  return bound;
}

void ViewerServer::serve(std::vector<WebFile> bake_export) {
  // Filled before the first request can arrive: listening starts below.
  impl_->bake_export = std::move(bake_export);
  for (const EmbeddedText& page : viewerPageFiles()) {
    impl_->files["/" + std::string(page.name)] = {page.text, mediaTypeOf(page.name)};
  }
  impl_->files["/"] = impl_->files.at("/index.html");
  for (const WebFile& file : impl_->bake_export) {
    impl_->files[kViewerBakePrefix + file.name] = {file.bytes, file.media_type};
  }
  impl_->server.listen_after_bind();
  impl_->served = true;
}

void ViewerServer::stop() {
  // httplib ignores a stop that comes before it listens: a stop asked for
  // while the page is still being prepared waits for serving to start.
  constexpr auto kPoll = std::chrono::milliseconds(10);
  while (!impl_->server.is_running() && !impl_->served) std::this_thread::sleep_for(kPoll);
  impl_->server.stop();
}

}  // namespace skybake
