// Transports over REAL pseudo-terminals and loopback TCP: raw bytes both ways, timeouts,
// the far end vanishing, and clear errors for bad port names and settings.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <pty.h>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include "drivers/transport/serial_ports.hpp"
#include "drivers/transport/transport.hpp"
#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers {
namespace {

struct Pty {
  int master = -1, slave = -1;
  std::string name;
  Pty() {
    char buffer[128];
    EXPECT_EQ(::openpty(&master, &slave, buffer, nullptr, nullptr), 0);
    name = buffer;
  }
  ~Pty() {
    if (master >= 0) ::close(master);
    if (slave >= 0) ::close(slave);
  }
};

TEST(Transport, PtyCarriesRawBytesBothWays) {
  Pty pty;
  SerialSettings settings;
  settings.baud = 9600;
  OpenResult opened = open_transport(pty.name, settings, 1);
  ASSERT_TRUE(opened.transport) << opened.error;
  EXPECT_NE(opened.transport->describe().find("9600 8N1"), std::string::npos) << opened.transport->describe();
  EXPECT_EQ(opened.transport->wire_baud(), 9600);
  // Raw mode: CR, LF, XON/XOFF and ctrl-X pass untouched, nothing is echoed.
  const std::string bytes("G1 X1\r\n\x11\x13\x18\x00\xff", 12);
  ASSERT_TRUE(opened.transport->write(bytes, 1).ok);
  std::string at_master(64, '\0');
  const ssize_t got = ::read(pty.master, at_master.data(), at_master.size());
  ASSERT_EQ(got, static_cast<ssize_t>(bytes.size()));
  EXPECT_EQ(at_master.substr(0, static_cast<size_t>(got)), bytes);
  ASSERT_EQ(::write(pty.master, "ok\r\n", 4), 4);
  std::string reply;
  ASSERT_TRUE(opened.transport->read(reply, 1).ok);
  EXPECT_EQ(reply, "ok\r\n");
  // Nothing more arrives: read times out with ok status and no bytes.
  reply.clear();
  const IoStatus quiet = opened.transport->read(reply, 0.05);
  EXPECT_TRUE(quiet.ok);
  EXPECT_TRUE(reply.empty());
}

TEST(Transport, DeviceVanishingIsReportedAsClosed) {
  auto pty = std::make_unique<Pty>();
  OpenResult opened = open_transport(pty->name, {}, 1);
  ASSERT_TRUE(opened.transport) << opened.error;
  pty.reset();  // the "USB adapter" is unplugged
  std::string bytes;
  IoStatus status = opened.transport->read(bytes, 0.5);
  EXPECT_FALSE(status.ok);
  EXPECT_TRUE(status.closed);
  EXPECT_TRUE(status.error.find("lost") != std::string::npos || status.error.find("closed") != std::string::npos) << status.error;
}

TEST(Transport, DeviceVanishingWhileWritingIsALostConnection) {
  // The write side may notice an unplugged adapter before the read side does (EIO on the tty); the
  // operator must read the same "connection lost" either way (seen once in CI: "write failed").
  auto pty = std::make_unique<Pty>();
  OpenResult opened = open_transport(pty->name, {}, 1);
  ASSERT_TRUE(opened.transport) << opened.error;
  pty.reset();
  const IoStatus status = opened.transport->write(std::string(4096, 'x'), 0.5);
  EXPECT_FALSE(status.ok);
  EXPECT_TRUE(status.closed) << status.error;
  EXPECT_NE(status.error.find("connection lost"), std::string::npos) << status.error;
}

TEST(Transport, TcpLoopbackAndRefusedConnection) {
  const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(listener, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  ASSERT_EQ(::listen(listener, 1), 0);
  socklen_t length = sizeof address;
  ::getsockname(listener, reinterpret_cast<sockaddr*>(&address), &length);
  const int port = ntohs(address.sin_port);
  OpenResult opened = open_transport("tcp://127.0.0.1:" + std::to_string(port), {}, 1);
  ASSERT_TRUE(opened.transport) << opened.error;
  EXPECT_EQ(opened.transport->wire_baud(), 0);
  const int peer = ::accept(listener, nullptr, nullptr);
  ASSERT_TRUE(opened.transport->write("IN;", 1).ok);
  char buffer[8] = {0};
  EXPECT_EQ(::read(peer, buffer, sizeof buffer), 3);
  ::close(peer);
  std::string bytes;
  IoStatus status = opened.transport->read(bytes, 1);
  EXPECT_FALSE(status.ok);
  EXPECT_TRUE(status.closed);
  // Writing to a closed connection is an error result, never a SIGPIPE that kills the process.
  IoStatus first = opened.transport->write("PU;", 1), second = opened.transport->write("PU;", 1);
  EXPECT_FALSE(first.ok && second.ok);
  ::close(listener);
  const OpenResult refused = open_transport("tcp://127.0.0.1:" + std::to_string(port), {}, 1);
  EXPECT_FALSE(refused.transport);
  EXPECT_NE(refused.error.find("cannot connect"), std::string::npos) << refused.error;
}

TEST(Transport, BadNamesAndSettingsGiveClearErrors) {
  Pty pty;
  SerialSettings settings;
  settings.baud = 12345;
  EXPECT_NE(open_transport(pty.name, settings, 1).error.find("unsupported baud rate 12345"), std::string::npos);
  settings = {};
  settings.data_bits = 9;
  EXPECT_NE(open_transport(pty.name, settings, 1).error.find("data bits"), std::string::npos);
  EXPECT_NE(open_transport("/dev/lastcut-no-such-port", {}, 1).error.find("no such port"), std::string::npos);
  EXPECT_NE(open_transport("/etc/hostname", {}, 1).error.find("not a serial port"), std::string::npos);
  EXPECT_NE(open_transport("tcp://nowhere", {}, 1).error.find("want host:port"), std::string::npos);
  EXPECT_NE(open_transport("", {}, 1).error.find("no port"), std::string::npos);
  FlowControl flow;
  EXPECT_TRUE(parse_flow_control("rtscts", flow));
  EXPECT_EQ(flow, FlowControl::RtsCts);
  EXPECT_FALSE(parse_flow_control("hardware", flow));
}

TEST(SerialPorts, UsbNamesAreCheckedAndResolvedAgainstWhatIsPlugged) {
  std::string device, error;
  EXPECT_FALSE(resolve_usb_port("usb:403:6001", device, error));
  EXPECT_NE(error.find("usb:VID:PID"), std::string::npos) << error;
  // An adapter id no machine has: must fail with a pointer to `lastcut ports`.
  EXPECT_FALSE(resolve_usb_port("usb:ffff:fffe:NOSUCH", device, error));
  EXPECT_NE(error.find("lastcut ports"), std::string::npos) << error;
  for (const auto& port : list_serial_ports()) {
    EXPECT_FALSE(port.device.empty());
    if (port.usb) {
      EXPECT_EQ(port.stable_name().rfind("usb:", 0), 0u);
    }
  }
  SerialPortInfo info;
  info.usb = true, info.usb_vid = 0x0403, info.usb_pid = 0x6001, info.usb_serial = "A10K3X";
  EXPECT_EQ(info.stable_name(), "usb:0403:6001:A10K3X");
}

}  // namespace
}  // namespace lastcut::drivers
