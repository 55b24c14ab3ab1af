// Progress on stderr: a live bar (stage, percent, elapsed) on a terminal, one
// line per finished stage otherwise (logs stay readable).
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

#include "baker/stages/progress.h"

namespace skybake::cli {

class TerminalProgress final : public ProgressSink {
 public:
  TerminalProgress();
  void beginStage(const std::string& name, size_t work_units) override;
  void advance(size_t units) override;
  void endStage(double seconds) override;

 private:
  void draw(size_t done);

  bool interactive_;
  std::string stage_;
  size_t total_ = 1;
  std::atomic<size_t> done_{0};
  std::mutex draw_mutex_;
  std::chrono::steady_clock::time_point bake_start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace skybake::cli
