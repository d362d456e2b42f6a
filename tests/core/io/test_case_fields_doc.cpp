// docs/case-file.md's field table is the case schema's: the document holds exactly what
// io::CaseFieldsMarkdown() generates (regenerate with `filmdyn case-fields --markdown`), and the
// table has one row per schema field with its range and the default case's value.
#include <QtTest>
#include <fstream>
#include <sstream>

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
};

QTEST_GUILESS_MAIN(TestCaseFieldsDoc)
#include "test_case_fields_doc.moc"
