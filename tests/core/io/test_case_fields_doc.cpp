// docs/case-file.md's field table is the case schema's: the document holds exactly what
// io::CaseFieldsMarkdown() generates (regenerate with `filmdyn case-fields --markdown`), and the
// table has one row per schema field with its range and the default case's value; every number
// the table shows as a closed bound or a default is one the field allows when typed back.
#include <QtTest>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/case_fields_doc.hpp"

class TestCaseFieldsDoc : public QObject {
  Q_OBJECT
 private slots:
  void documentMatchesTheSchema() {
    const std::string generated = filmdyn::io::CaseFieldsMarkdown();
    // One row per field (+ header and rule), each naming its path and allowed values.
    std::size_t rows = 0;
    for (char ch : generated) rows += ch == '\n';
    QCOMPARE(rows, filmdyn::engine::CaseSchema().size() + 2);
    QVERIFY(generated.find("| `big_end.mesh_theta` | - | integer in [8, 5000] | 100 |") !=
            std::string::npos);
    QVERIFY(generated.find("| `geometry.pin_offset` | m | [-0.01, 0.01] | 0.0007 |") !=
            std::string::npos);

    std::ifstream in(std::string(FILMDYN_SOURCE_DIR) + "/docs/case-file.md");
    QVERIFY(in.good());
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    const std::string begin = "<!-- case-fields:begin -->\n", end = "<!-- case-fields:end -->";
    const auto a = doc.find(begin), b = doc.find(end);
    QVERIFY2(a != std::string::npos && b != std::string::npos, "markers missing");
    const std::string table = doc.substr(a + begin.size(), b - a - begin.size());
    if (table != generated) {
      const std::string path = std::string(FILMDYN_BINARY_DIR) + "/case-fields.md";
      std::ofstream(path) << generated;
      QFAIL(("docs/case-file.md's field table is stale; the schema's table is in " + path +
             " (or run `filmdyn case-fields --markdown`)")
                .c_str());
    }
  }

  // A user copies a bound or a default from the table (or from an error message) into a case:
  // it must be allowed. Bounds and defaults at a range's end that ten digits would round outward
  // (8 pi as 25.13274123, 1/9 as 0.1111111111) are shown with every digit.
  void boundsAndDefaultsShownAreAllowed() {
    using filmdyn::engine::CaseField;
    using filmdyn::engine::FieldKind;
    const std::string table = filmdyn::io::CaseFieldsMarkdown();
    const std::regex number(R"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)");
    // The text, read whole as a number, is one the field allows.
    auto allowed = [](const CaseField& f, const std::string& text) {
      double v = 0.0;
      if (!filmdyn::ParseNumber(text, v)) return false;
      try {
        f.Check(v);
        return true;
      } catch (const filmdyn::InputError&) {
        return false;
      }
    };
    int bounds = 0, defaults = 0;
    std::istringstream rows(table);
    std::string row;
    while (std::getline(rows, row)) {
      if (row.rfind("| `", 0) != 0) continue;
      const std::string inner = row.substr(2, row.size() - 4);  // without "| " and " |"
      std::vector<std::string> cells;
      for (std::size_t at = 0;;) {
        const std::size_t bar = inner.find(" | ", at);
        cells.push_back(inner.substr(at, bar == std::string::npos ? bar : bar - at));
        if (bar == std::string::npos) break;
        at = bar + 3;
      }
      QVERIFY2(cells.size() >= 4, row.c_str());
      const std::string path = cells[0].substr(1, cells[0].size() - 2);
      const CaseField* f = filmdyn::engine::FindCaseField(path);
      QVERIFY2(f != nullptr, path.c_str());
      if (f->kind != FieldKind::kNumber && f->kind != FieldKind::kNumberList) continue;
      const std::string& range = cells[2];
      const auto open = range.find_first_of("[("), comma = range.find(", ", open);
      if (open != std::string::npos && comma != std::string::npos) {
        const std::string lo = range.substr(open + 1, comma - open - 1);
        const std::string hi = range.substr(comma + 2, range.size() - comma - 3);
        if (range[open] == '[') {
          QVERIFY2(allowed(*f, lo), (path + ": lower bound " + lo).c_str());
          ++bounds;
        }
        if (range.back() == ']') {
          QVERIFY2(allowed(*f, hi), (path + ": upper bound " + hi).c_str());
          ++bounds;
        }
      } else if (range.rfind("≥ ", 0) == 0) {
        QVERIFY2(allowed(*f, range.substr(std::string("≥ ").size())), path.c_str());
        ++bounds;
      }
      const std::string& shown = cells[3];
      for (std::sregex_iterator it(shown.begin(), shown.end(), number), end; it != end; ++it) {
        QVERIFY2(allowed(*f, it->str()), (path + ": default " + it->str()).c_str());
        ++defaults;
      }
    }
    QVERIFY(bounds > 100 && defaults > 100);
    // The case that was refused: the JFO run-in's upper bound and default, 8 pi.
    const CaseField* run_in = filmdyn::engine::FindCaseField("solver.jfo_run_in_angle");
    QCOMPARE(run_in->RangeText(), std::string("[0, 25.132741228718345]"));
    QVERIFY(table.find("| [0, 25.132741228718345] | 25.132741228718345 |") != std::string::npos);
    // A value just past it: the message's value and bound differ where they are shown.
    try {
      run_in->Check(25.13274123);
      QFAIL("25.13274123 > 8 pi was allowed");
    } catch (const filmdyn::InputError& e) {
      QCOMPARE(e.value(), std::string("25.13274123"));
      QVERIFY2(std::string(e.what()).find("[0, 25.132741228718345]") != std::string::npos,
               e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestCaseFieldsDoc)
#include "test_case_fields_doc.moc"
