#pragma once
// StatusObserver: what a station tells whoever shows live status (daemon/status publishes it
// over MQTT), the same on a spool and on a ledger node. Called from the station's own threads
// (main, compute workers, one per cutter) right after the change is durable; an implementation
// must return at once and never block, and must be thread-safe. Without an observer the station
// runs exactly as before.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "daemon/job/job_event.hpp"

namespace lastcut::daemon {

// What one cutter is doing now.
struct CutterStatus {
  std::string cutter;  // [cutters.<name>]
  // idle: nothing to cut | sending: a batch is being cut | waiting: a batch waits because the
  // cutter is not ready (alarm, switched off, refused before cutting) | held: the last batch was
  // interrupted and held, the machine may hold a partly cut hide (until the next batch starts).
  std::string state = "idle";
  std::string batch;   // the batch being cut, waiting or held; "" when idle
  std::string reason;  // why waiting or held, one line
  std::size_t lines_sent = 0, lines_total = 0;  // of the batch's cut file, acknowledged by the cutter
  std::size_t bytes_sent = 0, bytes_total = 0;
};

// One nesting done: a strip batch of a material, or the waiting pieces on a hide. What the cutting
// room follows per material and per hide: pieces placed, pieces left waiting, the yield.
struct NestingStatus {
  std::string material;
  std::string hide;       // the hide's id; "" for a strip batch
  std::string batch;      // the batch id
  std::string cutter;
  int pieces_placed = 0;
  int pieces_waiting = 0;  // a hide: the pieces of the jobs that wait for the next hide
  int jobs_placed = 0, jobs_waiting = 0;
  double utilisation = 0;  // placed piece area / the material used (a hide's usable area), 0..1
};

// {"material","hide","batch","cutter","pieces_placed","pieces_waiting","jobs_placed","jobs_waiting","utilisation"}:
// the same on MQTT and on the operator page.
nlohmann::json to_json(const NestingStatus& status);

class StatusObserver {
 public:
  virtual ~StatusObserver() = default;
  // A job changed stage, or got a note on the way (such as an attempt).
  virtual void job_changed(const JobEvent& event) = 0;
  // A cutter changed state or reported progress (at most every ~100 ms while sending).
  virtual void cutter_changed(const CutterStatus& status) = 0;
  // A batch or a hide was nested (its layout and cut file written). Observers that show no
  // materials may ignore it.
  virtual void nesting_done(const NestingStatus& /*status*/) {}
};

}  // namespace lastcut::daemon
