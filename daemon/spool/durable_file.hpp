#pragma once
// Crash-safe file operations for the spool (the Postfix/maildir discipline): a file is written
// to a temporary name in the same folder, fsync'ed, renamed over the final name, and the folder
// is fsync'ed, so after a power cut a reader sees either the old or the new content, never half.
// All functions return an empty string on success or one line saying what failed.
#include <filesystem>
#include <string>
#include <string_view>

namespace lastcut::daemon {

std::string write_file_durably(const std::filesystem::path& file, std::string_view content);
std::string fsync_folder(const std::filesystem::path& folder);
// rename(2) plus fsync of both folders. Across file systems (EXDEV) the file is copied to a
// temporary name next to the target, fsync'ed, renamed, and only then the source removed.
std::string move_durably(const std::filesystem::path& from, const std::filesystem::path& to);
// Copies a regular file durably (temporary name, fsync, rename).
std::string copy_file_durably(const std::filesystem::path& from, const std::filesystem::path& to);
// Names starting with this prefix are unfinished and never read by anyone.
inline constexpr std::string_view kTemporaryPrefix = ".tmp-";

}  // namespace lastcut::daemon
