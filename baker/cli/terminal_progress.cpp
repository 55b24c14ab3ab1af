#include "baker/cli/terminal_progress.h"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

namespace skybake::cli {
namespace {

// Redraw at most this often: a bar that redraws per texel row costs more
// than the rows.
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr int kBarWidth = 30;

}  // namespace

TerminalProgress::TerminalProgress()
    : interactive_(::isatty(STDERR_FILENO) != 0),
      bake_start_(std::chrono::steady_clock::now()),
      last_draw_(bake_start_) {}

void TerminalProgress::beginStage(const std::string& name, size_t work_units) {
  stage_ = name;
  total_ = std::max<size_t>(work_units, 1);
  done_ = 0;
  if (interactive_) draw(0);
}

void TerminalProgress::advance(size_t units) {
  const size_t done = done_.fetch_add(units) + units;
  if (!interactive_) return;
  // Only one thread draws; the others carry on computing.
  std::unique_lock lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const auto now = std::chrono::steady_clock::now();
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

void TerminalProgress::endStage(double seconds) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - bake_start_).count();
  if (interactive_) {
    fmt::print(stderr, "\r\033[K");
  }
  fmt::print(stderr, "{:<36} done in {:6.2f} s  (elapsed {:6.1f} s)\n", stage_, seconds, elapsed);
}

}  // namespace skybake::cli
