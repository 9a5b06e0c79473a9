// termios backend: raw 8N1-style line settings on a tty or pty, then FdTransport for I/O.
#include "drivers/transport/termios_transport.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include "drivers/transport/fd_transport.hpp"

namespace lastcut::drivers {

bool baud_to_speed(int baud, unsigned& speed) {
  switch (baud) {
    case 1200: speed = B1200; return true;
    case 2400: speed = B2400; return true;
    case 4800: speed = B4800; return true;
    case 9600: speed = B9600; return true;
    case 19200: speed = B19200; return true;
    case 38400: speed = B38400; return true;
    case 57600: speed = B57600; return true;
    case 115200: speed = B115200; return true;
    case 230400: speed = B230400; return true;
    case 460800: speed = B460800; return true;
    case 921600: speed = B921600; return true;
    default: return false;
  }
}

namespace {

std::string framing(const SerialSettings& s) {
  return std::to_string(s.baud) + " " + std::to_string(s.data_bits) + s.parity + std::to_string(s.stop_bits) + " " +
         to_string(s.flow);
}

}  // namespace

OpenResult open_termios_transport(const std::string& path, const SerialSettings& settings) {
  unsigned speed = 0;
  if (!baud_to_speed(settings.baud, speed)) return {nullptr, path + ": unsupported baud rate " + std::to_string(settings.baud)};
  if (settings.data_bits < 5 || settings.data_bits > 8) return {nullptr, path + ": data bits must be 5..8"};
  if (settings.stop_bits != 1 && settings.stop_bits != 2) return {nullptr, path + ": stop bits must be 1 or 2"};
  if (settings.parity != 'N' && settings.parity != 'E' && settings.parity != 'O') {
    return {nullptr, path + ": parity must be none, even or odd"};
  }
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return {nullptr, "cannot open " + path + ": " + std::strerror(errno)};
  termios tio{};
  if (::tcgetattr(fd, &tio) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    return {nullptr, path + " is not a serial port or terminal: " + why};
  }
  ::cfmakeraw(&tio);
  tio.c_cflag &= ~static_cast<tcflag_t>(CSIZE | PARENB | PARODD | CSTOPB | CRTSCTS);
  static const tcflag_t sizes[] = {CS5, CS6, CS7, CS8};
  tio.c_cflag |= sizes[settings.data_bits - 5] | CREAD | CLOCAL;
  if (settings.parity != 'N') tio.c_cflag |= PARENB;
  if (settings.parity == 'O') tio.c_cflag |= PARODD;
  if (settings.stop_bits == 2) tio.c_cflag |= CSTOPB;
  // Software flow control is done by the protocol code (it must see XOFF to report a stall),
  // so the kernel must pass XON/XOFF bytes through: IXON stays off here.
  if (settings.flow == FlowControl::RtsCts) tio.c_cflag |= CRTSCTS;
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, speed);
  ::cfsetospeed(&tio, speed);
  if (::tcsetattr(fd, TCSANOW, &tio) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    return {nullptr, path + ": cannot set " + framing(settings) + ": " + why};
  }
  ::tcflush(fd, TCIOFLUSH);
  return {std::make_unique<FdTransport>(fd, "tty " + path + " " + framing(settings), settings.baud, true), ""};
}

}  // namespace lastcut::drivers
