#pragma once
// Test harness for the daemon's end-to-end tests: real processes (lastcutd, lastcut-sim,
// lastcut generate) started with fork/exec, a scratch folder per test, waiting with a deadline.
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tests/support/child_process.hpp"

namespace lastcut::daemon::testing {

std::filesystem::path binary(const std::string& name);  // LASTCUT_BINARY_DIR/bin/<name>

// A child process; killed (SIGKILL) in the destructor if still running.
using Process = lastcut::test::ChildProcess;

// Polls `done` every 50 ms until it is true or timeout_s passes; returns its last value.
bool wait_until(const std::function<bool()>& done, double timeout_s);
// Runs a command to completion; returns its exit status.
int run_command(const std::vector<std::string>& argv, const std::filesystem::path& log_file);

std::string read_text(const std::filesystem::path& file);
void write_text(const std::filesystem::path& file, const std::string& text);
// Number of entries (not starting with '.') in a folder.
int count_entries(const std::filesystem::path& folder);
// How often `needle` occurs in `haystack`.
int count_occurrences(const std::string& haystack, const std::string& needle);
// A fresh empty folder under the build tree for one test.
std::filesystem::path scratch_folder(const std::string& name);
// Moves a finished file into the watch folder the way uploaders should: write elsewhere, rename.
void drop(const std::filesystem::path& file, const std::filesystem::path& watch_dir, const std::string& name);

// lastcut-sim `protocol` (grbl | hpgl) on a pseudo-terminal linked at `link`, moving instantly,
// recording what it receives in the folder `record`, with `--fault fault` unless it is empty;
// waits (20 s at most) for its "ready:" line in `log`. Null, with the log in `error`, if it did not start.
std::unique_ptr<Process> start_simulator(const std::string& protocol, const std::filesystem::path& link,
                                         const std::filesystem::path& record, const std::string& fault,
                                         const std::filesystem::path& log, std::string& error);
// The bytes a simulator of `protocol` recorded in the folder `record` (after it stopped).
std::string simulator_received(const std::string& protocol, const std::filesystem::path& record);

}  // namespace lastcut::daemon::testing
