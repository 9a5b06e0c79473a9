#pragma once
// The simulators' end of a link: a pseudo-terminal with a symlink at a chosen path (so the
// daemon, `lastcut send` or an operator's terminal program can open it like a serial port),
// or a TCP listener on 127.0.0.1.
#include <string>

namespace lastcut::drivers::sim {

struct PtyLink {
  int master = -1;        // the simulator reads and writes here
  int slave_keep = -1;    // held open so the pty survives clients closing and reopening it
  std::string slave_name; // /dev/pts/N
  std::string link_path;  // the symlink pointing at slave_name
};

// Creates a raw pty and the symlink `link_path` -> /dev/pts/N (replacing a stale symlink).
bool open_pty_link(const std::string& link_path, PtyLink& pty, std::string& error);
// Removes the symlink and closes both ends: clients see the device vanish (EIO), like a pulled cable.
void close_pty_link(PtyLink& pty);

// Listens on 127.0.0.1:port (loopback only). Returns the descriptor or -1 with `error`.
int listen_loopback(int port, std::string& error);

}  // namespace lastcut::drivers::sim
