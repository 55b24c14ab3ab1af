// How a bake tells its caller how far it has come. Stages announce themselves
// with their amount of work; worker threads report finished units.
#pragma once

#include <atomic>
#include <cstddef>
#include <string>

namespace skybake {

class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  // Called by the bake's controlling thread.
  virtual void beginStage(const std::string& name, size_t work_units) = 0;
  // Called from any worker thread, concurrently.
  virtual void advance(size_t units) = 0;
  // Called by the controlling thread.
  virtual void endStage(double seconds) = 0;
  // Something the user should know that does not stop the work (values
  // found bad and recomputed, results that could not be kept), said once.
  // Called by the controlling thread; ignored unless a sink shows it.
  virtual void note(const std::string& text) { (void)text; }
};

class SilentProgress final : public ProgressSink {
 public:
  void beginStage(const std::string&, size_t) override {}
  void advance(size_t) override {}
  void endStage(double) override {}
};

}  // namespace skybake
