// Fuzz target: the HP-GL device's replies (drivers/hpgl/hpgl_job.hpp). The HPGL driver reads
// answers to ESC.O (status), ESC.E (device error), ESC.B (buffer space) and OA (position), plus
// XON/XOFF bytes, from the cutter; those readers are private to hpgl_job.cpp, so the target runs
// the real run_hpgl_job against a scripted link (ScriptedLink) whose device side is the fuzz
// input. Byte 0 picks the handshake (status queries, ESC.B or XON/XOFF); the rest is what the
// device sends, delivered a few bytes per read; when it runs out the link reports "closed", so
// no run waits for a timeout. A cutter on a wrong baud rate or a noisy cable sends anything at all.
//
// What counts as fine: run_hpgl_job returns a SendResult (Done, Failed or Interrupted, with a
// reason) for any reply. It documents no exception, so none is caught: any throw, crash, hang or
// sanitizer report surfaces as a libFuzzer crash or timeout.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "drivers/hpgl/hpgl_job.hpp"

namespace {

using lastcut::drivers::IoStatus;

// A link whose device answers with a fixed script of bytes and takes every byte written.
class ScriptedLink : public lastcut::drivers::Transport {
 public:
  explicit ScriptedLink(std::string_view script) : script_(script) {}
  IoStatus read(std::string& out, double) override {
    if (script_.empty()) return IoStatus::failure("scripted device has no more bytes", true);
    const size_t take = std::min<size_t>(script_.size(), 1 + static_cast<unsigned char>(script_.front()) % 7);
    out.append(script_.substr(0, take));
    script_.remove_prefix(take);
    return IoStatus::success();
  }
  IoStatus write(std::string_view, double) override { return IoStatus::success(); }
  IoStatus drain(double) override { return IoStatus::success(); }
  void close() override {}
  std::string describe() const override { return "scripted fuzz device"; }
  int wire_baud() const override { return 0; }

 private:
  std::string_view script_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  lastcut::drivers::CutterConfig config;
  config.name = "fuzz";
  // Answers are waited for up to timeout_s, but the scripted link never makes anyone wait: when its
  // bytes run out it reports the link closed. Only a full ESC.B buffer ("0") sleeps, 20 ms a time,
  // which the short -max_len of this target (scripts/fuzz.sh) keeps to a few seconds.
  config.timeout_s = 1;
  switch (data[0] % 3) {
    case 0: config.hpgl_status_queries = true; break;
    case 1: config.hpgl_handshake = "escb"; break;
    default: config.flow = "xonxoff"; config.hpgl_status_queries = true; break;
  }
  ScriptedLink link(std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1));
  const std::atomic<bool> cancel{false};
  const std::string program = "IN;SP1;PU0,0;PD400,0,400,400,0,400,0,0;PU;SP0;";
  const lastcut::drivers::SendResult result = lastcut::drivers::hpgl::run_hpgl_job(link, config, program, {}, cancel);
  if (result.reason.empty()) std::abort();  // every outcome says why
  return 0;
}
