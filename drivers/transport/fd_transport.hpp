#pragma once
// FdTransport: read/write with timeouts on a non-blocking file descriptor (tty, pty or socket),
// shared by the termios, libserialport and TCP transports.
#include <string>

#include "drivers/transport/transport.hpp"

namespace lastcut::drivers {

class FdTransport : public Transport {
 public:
  // Takes ownership of `fd` (closed by close()/destructor unless owns_fd is false).
  FdTransport(int fd, std::string description, int wire_baud, bool is_tty, bool owns_fd = true);
  ~FdTransport() override;
  FdTransport(const FdTransport&) = delete;
  FdTransport& operator=(const FdTransport&) = delete;

  IoStatus read(std::string& out, double timeout_s) override;
  IoStatus write(std::string_view data, double timeout_s) override;
  IoStatus drain(double timeout_s) override;
  void close() override;
  std::string describe() const override { return description_; }
  int wire_baud() const override { return wire_baud_; }

 protected:
  int fd() const { return fd_; }

 private:
  int fd_;
  std::string description_;
  int wire_baud_;
  bool is_tty_;
  bool owns_fd_;
};

}  // namespace lastcut::drivers
