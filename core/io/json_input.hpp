#pragma once
/// @file The one JSON parser of FilmDyn's input files (cases, studies, the GUI's case text).
#include <nlohmann/json.hpp>
#include <string>

namespace filmdyn::io {

/// Parses the JSON text of an input file with two rules nlohmann's parser does not keep:
/// - nesting is bounded (`max_depth` levels): an input is a few levels deep, and a value nested
///   10^5 deep would exhaust the stack of every recursive walk of it later;
/// - every key appears once in its object: the parser would keep the last of a repeated key and
///   silently drop the other value.
/// Errors are InputErrors naming `source` (and the key's path for a repeated key); `kind` says
/// what the file is ("a case file") in the nesting error. A path's list index reads as its
/// file's other errors do: "pressure_curves.0.rpm" (cases), "factors[0].path" (`bracketed`).
nlohmann::json ParseInputJson(const std::string& text, const std::string& source, int max_depth,
                              const std::string& kind, bool bracketed = false);

}  // namespace filmdyn::io
