#pragma once
/// @file The case editor's tooltips, from core's case schema alone (core/engine/case_schema.hpp):
/// what an input is in plain words, its display unit, allowed range and default, and — as a
/// secondary line — where it sits in the case file. A field added to the schema gets its tooltip
/// with no change here.
#include <QString>

#include "core/engine/case_schema.hpp"

namespace filmdyn::ui {

/// The allowed values in display units: "(0, 10000] µm", "[-10, 10] mm", "integer in [8, 5000]",
/// "each [0, 180] °", "\"ideal\" or \"lubricated\"".
QString DisplayRangeText(const engine::CaseField& field);
/// A closed bound or a default in display units without the unit: six digits, or every digit
/// where those, typed back, would fall outside the field's range (a value at a range's end, such
/// as 1/9 or 8 pi).
QString DisplayTypable(double si, const engine::CaseField& field);
/// `shown`, a short form of si in display units, or every digit where `shown`, typed back, would
/// land on the other side of the field's range than si itself (core's FormatOnItsSide).
std::string DisplayOnItsSide(double si, const engine::CaseField& field, const std::string& shown);
/// The value of the default case (File → New) in display units with the unit: "25 µm",
/// "0, 7, 14, 21, 28 mm", "lubricated"; empty for long text.
QString DisplayDefaultText(const engine::CaseField& field);
/// Rich-text tooltip: the label, the plain-words description, "Unit · Allowed · Default", the
/// schema's note (source of the default), and "In the case file: <path>" in grey. `first`, if
/// given, leads as a paragraph of its own (a cell's whole text where the cell may elide it).
QString FieldToolTip(const engine::CaseField& field, const QString& first = {});

}  // namespace filmdyn::ui
