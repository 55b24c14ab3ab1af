// What colour and spectral bakes share: both run the order loop
// (bakeWavelengthPass) once per group of at most 4 wavelengths
// (BakeConfig::colour_groups), with progress named after the pass and one
// report for the whole bake.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "baker/bake/bake.h"

namespace skybake {

// The config of pass g: the settled config with group g's atmosphere, an
// ordinary bake of those wavelengths.
BakeConfig passConfig(const BakeConfig& settled, size_t g);

// The caller's progress with each stage named after its pass ("pass 2/4:
// single_scattering"), so that a user sees which of the repeated stages runs.
class PassProgress final : public ProgressSink {
 public:
  PassProgress(ProgressSink& inner, size_t pass, size_t passes) : inner_(inner), pass_(pass), passes_(passes) {}
  void beginStage(const std::string& name, size_t work_units) override;
  void advance(size_t units) override { inner_.advance(units); }
  void endStage(double seconds) override { inner_.endStage(seconds); }

 private:
  ProgressSink& inner_;
  size_t pass_, passes_;
};

// Adds pass `index` (of `pass_wavelengths_nm`) to the whole bake's report:
// one entry per stage and order, its seconds summed over the passes (the
// report, in every part's header, stays the size of one pass's); the orders
// decision (converged only if every pass did; the largest last-order share);
// the tail estimate (applied only if every pass applied it; each pass's
// reason); threads and the pass count. What each order added is the
// caller's to combine (colour and spectral bakes store it differently).
void addPassRun(const BakeReport& pass, size_t index, const std::vector<double>& pass_wavelengths_nm,
                BakeReport& report);

// The whole bake's wall and CPU time since `start` / `cpu_start` and its
// peak memory.
void finishPassesReport(std::chrono::steady_clock::time_point start, double cpu_start, BakeReport& report);

}  // namespace skybake
