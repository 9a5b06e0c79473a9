#include "daemon/spool/durable_file.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace lastcut::daemon {
namespace {

std::string errno_text(const std::string& what, const std::filesystem::path& path) {
  return what + " " + path.string() + ": " + std::strerror(errno);
}

std::filesystem::path temporary_name(const std::filesystem::path& file) {
  return file.parent_path() / (std::string(kTemporaryPrefix) + file.filename().string() + "-" + std::to_string(getpid()));
}

std::string write_all(int fd, const char* data, std::size_t size, const std::filesystem::path& path) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno_text("cannot write", path);
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return {};
}

}  // namespace

std::string fsync_folder(const std::filesystem::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return errno_text("cannot open folder", folder);
  const int rc = ::fsync(fd);
  std::string error = rc == 0 ? std::string() : errno_text("cannot fsync folder", folder);
  ::close(fd);
  return error;
}

std::string write_file_durably(const std::filesystem::path& file, std::string_view content) {
  const std::filesystem::path temporary = temporary_name(file);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return errno_text("cannot create", temporary);
  std::string error = write_all(fd, content.data(), content.size(), temporary);
  if (error.empty() && ::fsync(fd) != 0) error = errno_text("cannot fsync", temporary);
  ::close(fd);
  if (error.empty() && ::rename(temporary.c_str(), file.c_str()) != 0) error = errno_text("cannot rename onto", file);
  if (!error.empty()) {
    ::unlink(temporary.c_str());
    return error;
  }
  return fsync_folder(file.parent_path());
}

std::string copy_file_durably(const std::filesystem::path& from, const std::filesystem::path& to) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return errno_text("cannot open", from);
  const std::filesystem::path temporary = temporary_name(to);
  const int out = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (out < 0) {
    const std::string error = errno_text("cannot create", temporary);
    ::close(in);
    return error;
  }
  std::string error;
  char buffer[65536];
  while (error.empty()) {
    const ssize_t got = ::read(in, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      error = errno_text("cannot read", from);
    } else if (got == 0) {
      break;
    } else {
      error = write_all(out, buffer, static_cast<std::size_t>(got), temporary);
    }
  }
  if (error.empty() && ::fsync(out) != 0) error = errno_text("cannot fsync", temporary);
  ::close(in);
  ::close(out);
  if (error.empty() && ::rename(temporary.c_str(), to.c_str()) != 0) error = errno_text("cannot rename onto", to);
  if (!error.empty()) {
    ::unlink(temporary.c_str());
    return error;
  }
  return fsync_folder(to.parent_path());
}

std::string move_durably(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::rename(from.c_str(), to.c_str()) == 0) {
    std::string error = fsync_folder(to.parent_path());
    if (error.empty() && from.parent_path() != to.parent_path()) error = fsync_folder(from.parent_path());
    return error;
  }
  if (errno != EXDEV) return errno_text("cannot move " + from.string() + " to", to);
  if (std::filesystem::is_directory(from)) return "cannot move folder " + from.string() + " across file systems";
  std::string error = copy_file_durably(from, to);
  if (!error.empty()) return error;
  if (::unlink(from.c_str()) != 0) return errno_text("copied but cannot remove", from);
  return fsync_folder(from.parent_path());
}

}  // namespace lastcut::daemon
