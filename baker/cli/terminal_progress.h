// Progress on stderr: a live bar (stage, percent, elapsed) on a terminal;
// otherwise (logs) plain lines: once a stage has run a second, one per 10 %
// of it or per 10 s, whichever comes first, with the time so far, and one per
// finished stage.
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
  // "skybake: note: <text>" on its own line of stderr, escaped (it names files).
  void note(const std::string& text) override;

 private:
  void draw(size_t done);
  // Off a terminal: a line when the stage has passed its next step or has
  // been silent too long. Called with draw_mutex_ held.
  void logLine(size_t done, std::chrono::steady_clock::time_point now);

  bool interactive_;
  std::string stage_;
  size_t total_ = 1;
  std::atomic<size_t> done_{0};
  std::mutex draw_mutex_;
  std::chrono::steady_clock::time_point bake_start_;
  std::chrono::steady_clock::time_point last_draw_;
  // Guarded by draw_mutex_: the non-terminal lines' schedule.
  std::chrono::steady_clock::time_point stage_start_;
  std::chrono::steady_clock::time_point last_log_;
  size_t next_log_step_ = 1;
};

}  // namespace skybake::cli
