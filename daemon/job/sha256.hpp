#pragma once
// SHA-256 of a file, as 64 lowercase hex digits: how the spool recognises the same scan dropped
// twice. Implements FIPS PUB 180-4, "Secure Hash Standard", NIST 2015, section 6.2.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace lastcut::daemon {

std::string sha256_hex(std::string_view bytes);
// Empty optional when the file cannot be read.
std::optional<std::string> sha256_file_hex(const std::filesystem::path& file);

}  // namespace lastcut::daemon
