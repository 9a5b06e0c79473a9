// Fuzz target: the daemon's configuration loader (daemon/config/config_loader.hpp),
// load_daemon_config on a lastcut.toml file. The file is written by an operator, and a reload
// (SIGHUP) re-reads it while the daemon runs: a bad file must be refused, never half-applied,
// and never bring the daemon down.
//
// What counts as fine: load_daemon_config reports every problem in ConfigLoadResult::error (one
// line per problem, naming key and line) and leaves `config` empty. It documents no exception,
// so none is caught here: any throw, crash or sanitizer report surfaces as a libFuzzer crash.
// Relative paths in the file resolve against the temp folder; the loader only reads.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "daemon/config/config_loader.hpp"
#include "fuzz_input_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static lastcut::fuzz::FuzzInputFile file("lastcut.toml");
  const lastcut::daemon::ConfigLoadResult result = lastcut::daemon::load_daemon_config(file.write(data, size));
  if (!result.config && result.error.empty()) std::abort();  // a refusal must say why
  return 0;
}
