#include "engine/core/durable_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace lastcut {
namespace {

constexpr std::string_view kTemporaryPrefix = ".tmp-";

Status errno_failure(const std::string& what, const std::filesystem::path& path) {
  return Status::failure(what + " " + path.string() + ": " + std::strerror(errno));
}

// Hidden (no reader lists it) and unique per process (two writers never share one).
std::filesystem::path temporary_name(const std::filesystem::path& file) {
  return file.parent_path() /
         (std::string(kTemporaryPrefix) + file.filename().string() + "-" + std::to_string(getpid()));
}

Status write_all(int fd, const char* data, std::size_t size, const std::filesystem::path& path) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno_failure("cannot write", path);
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return Status::success();
}

Status copy_all(int in, int out, const std::filesystem::path& from, const std::filesystem::path& temporary) {
  char buffer[65536];
  for (;;) {
    const ssize_t got = ::read(in, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      return errno_failure("cannot read", from);
    }
    if (got == 0) return Status::success();
    if (Status written = write_all(out, buffer, static_cast<std::size_t>(got), temporary); !written) return written;
  }
}

// Fills a fresh temporary file next to `file` with `fill(fd)`, fsyncs it and renames it onto
// `file`; the temporary is removed on any failure.
template <typename Fill>
Status replace_durably(const std::filesystem::path& file, WriteSync sync, Fill fill) {
  const std::filesystem::path temporary = temporary_name(file);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return errno_failure("cannot create", temporary);
  Status status = fill(fd, temporary);
  if (status && sync == WriteSync::Fsync && ::fsync(fd) != 0) status = errno_failure("cannot fsync", temporary);
  ::close(fd);
  if (status && ::rename(temporary.c_str(), file.c_str()) != 0) status = errno_failure("cannot rename onto", file);
  if (!status) {
    ::unlink(temporary.c_str());
    return status;
  }
  return sync == WriteSync::Fsync ? fsync_folder(file.parent_path()) : Status::success();
}

}  // namespace

bool is_unfinished_write(std::string_view file_name) {
  return file_name.substr(0, kTemporaryPrefix.size()) == kTemporaryPrefix;
}

Status fsync_folder(const std::filesystem::path& folder_or_empty) {
  // A bare file name ("cut.nc") has an empty parent: that is the working folder.
  const std::filesystem::path folder = folder_or_empty.empty() ? std::filesystem::path(".") : folder_or_empty;
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return errno_failure("cannot open folder", folder);
  Status status = ::fsync(fd) == 0 ? Status::success() : errno_failure("cannot fsync folder", folder);
  ::close(fd);
  return status;
}

Status write_file_durably(const std::filesystem::path& file, std::string_view content, WriteSync sync) {
  return replace_durably(file, sync, [&](int fd, const std::filesystem::path& temporary) {
    return write_all(fd, content.data(), content.size(), temporary);
  });
}

Status copy_file_durably(const std::filesystem::path& from, const std::filesystem::path& to) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return errno_failure("cannot open", from);
  Status status = replace_durably(to, WriteSync::Fsync, [&](int out, const std::filesystem::path& temporary) {
    return copy_all(in, out, from, temporary);
  });
  ::close(in);
  return status;
}

Status move_durably(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::rename(from.c_str(), to.c_str()) == 0) {
    Status status = fsync_folder(to.parent_path());
    if (status && from.parent_path() != to.parent_path()) status = fsync_folder(from.parent_path());
    return status;
  }
  if (errno != EXDEV) return errno_failure("cannot move " + from.string() + " to", to);
  if (std::filesystem::is_directory(from)) {
    return Status::failure("cannot move folder " + from.string() + " across file systems");
  }
  if (Status copied = copy_file_durably(from, to); !copied) return copied;
  if (::unlink(from.c_str()) != 0) return errno_failure("copied but cannot remove", from);
  return fsync_folder(from.parent_path());
}

}  // namespace lastcut
