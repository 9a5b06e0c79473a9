#pragma once
// Runs a ByteDevice over a pty or a loopback TCP socket until asked to stop, modelling the
// serial wire: at `baud`, each byte takes 10 bit times (start + 8 data + stop) in each
// direction, because a pty itself moves bytes instantly. Injects the link faults
// (drop, stall) and writes the device's record to `record_dir`.
#include <atomic>
#include <filesystem>
#include <string>

#include "drivers/sim/byte_device.hpp"

namespace lastcut::drivers::sim {

struct ByteLinkOptions {
  std::string link_path;             // create a pty and this symlink ...
  int tcp_port = 0;                  // ... or listen on 127.0.0.1:tcp_port
  int baud = -1;                     // wire model: bits/s, 0 = not rate limited, -1 = the rate the client set on the pty
  std::filesystem::path record_dir;  // empty: record nothing
  Faults faults;
};

// Called once the link exists (pty created / socket listening), e.g. to print "ready".
using ReadyCallback = void (*)(const std::string& where);

// Returns 0 on a clean stop (stop set), 1 with `error` when the link could not be set up.
int run_byte_device(ByteDevice& device, const ByteLinkOptions& options, const std::atomic<bool>& stop,
                    ReadyCallback ready, std::string& error);

}  // namespace lastcut::drivers::sim
