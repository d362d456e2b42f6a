#pragma once
/// @file Reading input files named by the user: bounded, regular files only.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace filmdyn {

/// Checks an input file named by `field` (the option or case field that gave the path) before
/// it is read: it exists, is a regular file (no device, FIFO or folder: "/dev/zero" would never
/// end, a FIFO would wait for a writer forever) and holds at most `max_bytes` (a clear error
/// naming the field, the file's size and the limit). Throws InputError.
void RequireInputFile(const std::filesystem::path& path, const std::string& field,
                      std::uintmax_t max_bytes);

/// Reads a whole input file after RequireInputFile's checks (the size is checked again while
/// reading: a file that grows). Throws InputError.
std::string ReadInputFile(const std::filesystem::path& path, const std::string& field,
                          std::uintmax_t max_bytes);

/// A line or cell of an input file without the spaces, tabs and line ends around it.
std::string Trim(std::string_view text);

/// `text` with its ASCII letters in lower case (a header or keyword compared without case).
std::string Lower(std::string text);

}  // namespace filmdyn
