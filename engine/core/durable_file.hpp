#pragma once
// Crash-safe file operations (the Postfix/maildir discipline): a file is written to a temporary
// name in the same folder, fsync'ed, renamed over the final name, and the folder is fsync'ed, so
// after a power cut a reader sees either the old or the new content, never half.
// Every durable write of lastcut (spool state, molds, cut files, reports) goes through here, so
// there is one temporary name to recognise and clean up after a crash (is_unfinished_write).
// All functions return a Status whose error is one line saying what failed.
#include <filesystem>
#include <string_view>

#include "engine/core/status.hpp"

namespace lastcut {

enum class WriteSync {
  Fsync,       // file and folder fsync'ed: the new content survives a power cut
  AtomicOnly,  // rename only: for files rewritten every few seconds and worthless after a crash
};

Status write_file_durably(const std::filesystem::path& file, std::string_view content,
                          WriteSync sync = WriteSync::Fsync);
Status fsync_folder(const std::filesystem::path& folder);
// Copies a regular file durably (temporary name, fsync, rename).
Status copy_file_durably(const std::filesystem::path& from, const std::filesystem::path& to);
// rename(2) plus fsync of both folders. Across file systems (EXDEV) the file is copied to a
// temporary name next to the target, fsync'ed, renamed, and only then the source removed.
Status move_durably(const std::filesystem::path& from, const std::filesystem::path& to);

// True for the temporary names of the writes above: unfinished, never read, safe to remove
// once no writer runs (at start).
bool is_unfinished_write(std::string_view file_name);

}  // namespace lastcut
