#pragma once
/// @file A locale whose decimal point is a comma, for the tests that check numbers are read and
/// written the same in every locale. Qt's application objects set the C library's locale from the
/// environment (setlocale(LC_ALL, "")), so a user whose LANG is German or French runs FilmDyn
/// under one: there the C library's strtod reads "1.5" as 1 and printf writes "1,5".
#include <clocale>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace filmdyn::testing {

struct CommaLocale {
  std::string name;     ///< for setlocale, LANG, LC_ALL
  std::string locpath;  ///< LOCPATH it needs (a compiled one); empty for an installed one
};

/// Whether setlocale takes `name` (with LOCPATH = `locpath` when given) and its decimal point is
/// a comma. The locale and LOCPATH are set back.
inline bool IsCommaDecimalLocale(const std::string& name, const std::string& locpath = {}) {
  const char* old_path = std::getenv("LOCPATH");
  const std::optional<std::string> saved_path =
      old_path ? std::optional<std::string>(old_path) : std::nullopt;
  if (!locpath.empty()) setenv("LOCPATH", locpath.c_str(), 1);
  const std::string saved = std::setlocale(LC_ALL, nullptr);
  const bool comma = std::setlocale(LC_ALL, name.c_str()) != nullptr &&
                     std::string(std::localeconv()->decimal_point) == ",";
  std::setlocale(LC_ALL, saved.c_str());
  if (!locpath.empty()) {
    if (saved_path) {
      setenv("LOCPATH", saved_path->c_str(), 1);
    } else {
      unsetenv("LOCPATH");
    }
  }
  return comma;
}

/// A comma-decimal locale: an installed German or French one, or else de_DE.UTF-8 compiled with
/// localedef from the definitions of Debian's `locales` package into `scratch` (no root needed;
/// it then needs LOCPATH = scratch). Nothing when neither is possible.
inline std::optional<CommaLocale> FindCommaDecimalLocale(const std::filesystem::path& scratch) {
  for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8"}) {
    if (IsCommaDecimalLocale(name)) return CommaLocale{name, {}};
  }
  std::error_code ignored;
  std::filesystem::create_directories(scratch, ignored);
  // localedef exits non-zero on warnings about the definitions even when it writes the locale.
  const std::string command =
      "localedef -i de_DE -f UTF-8 '" + (scratch / "de_DE.UTF-8").string() + "' >/dev/null 2>&1";
  [[maybe_unused]] const int status = std::system(command.c_str());
  if (IsCommaDecimalLocale("de_DE.UTF-8", scratch.string())) {
    return CommaLocale{"de_DE.UTF-8", scratch.string()};
  }
  return std::nullopt;
}

/// The message of a test that finds no such locale.
inline constexpr char kNoCommaLocale[] =
    "no locale with a decimal comma: install Debian's `locales` package (scripts/install-deps.sh "
    "does)";

}  // namespace filmdyn::testing
