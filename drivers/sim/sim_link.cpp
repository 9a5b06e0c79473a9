// Pseudo-terminal and loopback TCP endpoints for the simulated cutters.
#include "drivers/sim/sim_link.hpp"

#include <arpa/inet.h>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <netinet/in.h>
#include <pty.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

namespace lastcut::drivers::sim {

bool open_pty_link(const std::string& link_path, PtyLink& pty, std::string& error) {
  termios raw{};
  ::cfmakeraw(&raw);
  raw.c_cflag |= CREAD | CLOCAL;
  char name[128] = {0};
  if (::openpty(&pty.master, &pty.slave_keep, name, &raw, nullptr) != 0) {
    error = std::string("cannot create a pseudo-terminal: ") + std::strerror(errno);
    return false;
  }
  ::fcntl(pty.master, F_SETFL, ::fcntl(pty.master, F_GETFL) | O_NONBLOCK);
  ::fcntl(pty.master, F_SETFD, FD_CLOEXEC);
  ::fcntl(pty.slave_keep, F_SETFD, FD_CLOEXEC);
  pty.slave_name = name;
  struct stat st{};
  if (::lstat(link_path.c_str(), &st) == 0) {
    if (!S_ISLNK(st.st_mode)) {
      error = link_path + " exists and is not a symlink: refusing to replace it";
      close_pty_link(pty);
      return false;
    }
    ::unlink(link_path.c_str());
  }
  if (::symlink(name, link_path.c_str()) != 0) {
    error = "cannot create symlink " + link_path + ": " + std::strerror(errno);
    close_pty_link(pty);
    return false;
  }
  pty.link_path = link_path;
  return true;
}

void close_pty_link(PtyLink& pty) {
  if (!pty.link_path.empty()) ::unlink(pty.link_path.c_str());
  pty.link_path.clear();
  if (pty.master >= 0) ::close(pty.master);
  if (pty.slave_keep >= 0) ::close(pty.slave_keep);
  pty.master = pty.slave_keep = -1;
}

int listen_loopback(int port, std::string& error) {
  const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) {
    error = std::string("socket: ") + std::strerror(errno);
    return -1;
  }
  int one = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(fd, 4) != 0) {
    error = "cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + std::strerror(errno);
    ::close(fd);
    return -1;
  }
  return fd;
}

}  // namespace lastcut::drivers::sim
