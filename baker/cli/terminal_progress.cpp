#include "baker/cli/terminal_progress.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

#include "data_formats/terminal_text.h"

namespace skybake::cli {
namespace {

// Redraw at most this often: a bar that redraws per texel row costs more
// than the rows.
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr int kBarWidth = 30;
// Off a terminal (a log file, a CI job), a line per 1/kLogSteps of a stage
// and at least one per kLogInterval: a long stage (a reference run takes
// hours) would otherwise leave the log silent until it ends, which reads as
// hung; more often would bury the log in lines.
constexpr size_t kLogSteps = 10;
constexpr auto kLogInterval = std::chrono::seconds(10);
// No such lines in a stage's first second: most bake stages end sooner, and
// ten lines each would bury a bake's log (its done line says enough).
constexpr auto kLogQuietStart = std::chrono::seconds(1);

}  // namespace

TerminalProgress::TerminalProgress()
    : interactive_(::isatty(STDERR_FILENO) != 0),
      bake_start_(std::chrono::steady_clock::now()),
      last_draw_(bake_start_) {}

void TerminalProgress::beginStage(const std::string& name, size_t work_units) {
  stage_ = name;
  total_ = std::max<size_t>(work_units, 1);
  done_ = 0;
  {
    const std::lock_guard lock(draw_mutex_);
    stage_start_ = std::chrono::steady_clock::now();
    last_log_ = stage_start_;
    next_log_step_ = 1;
  }
  if (interactive_) draw(0);
}

void TerminalProgress::advance(size_t units) {
  const size_t done = done_.fetch_add(units) + units;
  // Only one thread draws; the others carry on computing (a step it misses
  // is taken by the next advance, as `done` only grows).
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const auto now = std::chrono::steady_clock::now();
  if (!interactive_) {
    logLine(done, now);
    return;
  }
  if (now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  draw(done);
}

void TerminalProgress::draw(size_t done) {
  const double fraction = std::min(1.0, static_cast<double>(done) / total_);
  const int filled = static_cast<int>(fraction * kBarWidth);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - bake_start_).count();
  fmt::print(stderr, "\r\033[K{:<36} [{}{}] {:3.0f}%  {:6.1f} s", stage_, std::string(filled, '#'),
             std::string(kBarWidth - filled, '.'), 100.0 * fraction, elapsed);
  std::fflush(stderr);
}

void TerminalProgress::logLine(size_t done, std::chrono::steady_clock::time_point now) {
  // The finished stage gets endStage's line instead.
  if (done >= total_ || now - stage_start_ < kLogQuietStart) return;
  // Steps in integers: done / total_ >= step / kLogSteps, exactly.
  const size_t step = done * kLogSteps / total_;
  if (step < next_log_step_ && now - last_log_ < kLogInterval) return;
  last_log_ = now;
  // The step after the one just passed (not simply the next one: a late
  // line, after a quiet start or a missed lock, would be followed at once).
  next_log_step_ = step + 1;
  const double fraction = static_cast<double>(done) / total_;
  const double stage_s = std::chrono::duration<double>(now - stage_start_).count();
  const double elapsed = std::chrono::duration<double>(now - bake_start_).count();
  fmt::print(stderr, "{:<36} {:3.0f}% ({}/{}) after {:6.1f} s  (elapsed {:6.1f} s)\n", stage_, 100.0 * fraction, done,
             total_, stage_s, elapsed);
  std::fflush(stderr);
}

void TerminalProgress::endStage(double seconds) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - bake_start_).count();
  if (interactive_) {
    fmt::print(stderr, "\r\033[K");
  }
  fmt::print(stderr, "{:<36} done in {:6.2f} s  (elapsed {:6.1f} s)\n", stage_, seconds, elapsed);
}

void TerminalProgress::note(const std::string& text) {
  const std::lock_guard<std::mutex> lock(draw_mutex_);
  if (interactive_) fmt::print(stderr, "\r\033[K");
  fmt::print(stderr, "skybake: note: {}\n", terminalSafe(text));
}

}  // namespace skybake::cli
