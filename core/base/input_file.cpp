#include "core/base/input_file.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "core/base/input_error.hpp"

namespace filmdyn {

namespace {

InputError TooLarge(const std::filesystem::path& path, const std::string& field,
                    std::uintmax_t bytes, std::uintmax_t max_bytes) {
  return InputError(field, path.string(),
                    "is too large (" + std::to_string(bytes) + " bytes; at most " +
                        std::to_string(max_bytes) + ")");
}

}  // namespace

void RequireInputFile(const std::filesystem::path& path, const std::string& field,
                      std::uintmax_t max_bytes) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status)) {
    throw InputError(field, path.string(), "cannot open the file: it does not exist");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(field, path.string(),
                     "is not a regular file (a folder, device or pipe): give a file");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > max_bytes) throw TooLarge(path, field, size, max_bytes);
}

std::string ReadInputFile(const std::filesystem::path& path, const std::string& field,
                          std::uintmax_t max_bytes) {
  RequireInputFile(path, field, max_bytes);
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if (in == nullptr) {
    throw InputError(field, path.string(),
                     std::string("cannot open the file: ") + std::strerror(errno));
  }
  std::string text;
  char buffer[65536];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, in)) > 0) {
    text.append(buffer, got);
    if (text.size() > max_bytes) {  // grew while read
      std::fclose(in);
      throw TooLarge(path, field, text.size(), max_bytes);
    }
  }
  const bool failed = std::ferror(in) != 0;
  std::fclose(in);
  if (failed) throw InputError(field, path.string(), "cannot read the file");
  return text;
}

std::string Trim(std::string_view text) {
  const auto begin = text.find_first_not_of(" \t\r\n");
  if (begin == std::string_view::npos) return {};
  return std::string(text.substr(begin, text.find_last_not_of(" \t\r\n") - begin + 1));
}

std::string Lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace filmdyn
