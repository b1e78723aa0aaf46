#pragma once
/// \file
/// Sizes in bytes as people write and read them: "512M", "8G" in, "1.5 GiB" out.

#include <cstddef>
#include <optional>
#include <string>

namespace raylab {

/// Bytes in the binary unit that keeps three or four digits: "512 B", "3.4 KiB", "1.5 MiB",
/// "2.25 GiB".
std::string human_bytes(std::size_t bytes);

/// Parses a size such as "512M", "8G", "1.5GiB" or "4096" (bytes). Units are binary: K/KiB,
/// M/MiB, G/GiB, T/TiB, or B. Empty for text that is not a positive size below 10^18 bytes.
std::optional<std::size_t> parse_byte_size(const std::string& text);

}  // namespace raylab
