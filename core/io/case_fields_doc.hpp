#pragma once
/// @file The field table of docs/case-file.md, generated from the case schema with the embedded
/// default case's values and "assumed" notes (`filmdyn case-fields --markdown` prints it; a test
/// keeps the document equal to it).
#include <string>

namespace filmdyn::io {

/// One Markdown table row per case field: path, SI unit, allowed values, default, description
/// (with the default case's "assumed" reason where it marks the field).
std::string CaseFieldsMarkdown();
/// Plain text for a terminal: one line per field (path, unit, allowed values, label).
std::string CaseFieldsText();

}  // namespace filmdyn::io
