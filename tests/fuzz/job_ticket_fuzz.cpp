// Fuzz target: the job sidecar reader (daemon/job/job_ticket.hpp), read_job_ticket on a
// NAME.job.toml or NAME.job.json file. Sidecars are written by the workshop's order system or by
// hand and dropped in the watch folder next to a scan: outside input the daemon reads unattended.
// The daemon picks the format by extension; here an input starting with '{' (never valid TOML at
// the start of a file) is written as .job.json, anything else as .job.toml, so one target and one
// corpus cover both readers and the key checks they share.
//
// What counts as fine: read_job_ticket returns Result<JobTicket>; a bad sidecar is a failed
// Status with one line ("unknown key ...", "line 3: ..."). It documents no exception, and the
// daemon does not expect one from it, so no exception is caught here: any throw (a toml++ or
// nlohmann exception that slipped through, std::bad_alloc) is reported by libFuzzer as a crash.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "daemon/job/job_ticket.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static lastcut::fuzz::FuzzInputFile toml_file("scan.job.toml");
  static lastcut::fuzz::FuzzInputFile json_file("scan.job.json");
  lastcut::fuzz::FuzzInputFile& file = size > 0 && data[0] == '{' ? json_file : toml_file;
  const lastcut::Result<lastcut::daemon::JobTicket> ticket = lastcut::daemon::read_job_ticket(file.write(data, size));
  if (!ticket.ok() && ticket.error().empty()) std::abort();  // a refusal must say why
  return 0;
}
