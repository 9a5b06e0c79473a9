#include "daemon/spool/batch_lock.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace lastcut::daemon {

Result<BatchLock> BatchLock::take(const std::filesystem::path& batch_dir) {
  const std::filesystem::path file = batch_dir / ".lock";
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0640);
  if (fd < 0) return Status::failure("cannot open " + file.string() + ": " + std::strerror(errno));
  while (::flock(fd, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    const std::string why = std::strerror(errno);
    ::close(fd);
    return Status::failure("cannot lock " + file.string() + ": " + why);
  }
  return BatchLock(fd);
}

BatchLock::~BatchLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the descriptor releases the lock
}

}  // namespace lastcut::daemon
