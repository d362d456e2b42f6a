// `filmdyn validate`: every name its suite column prints selects those rows with --suite (the
// lubrication suite printed "bearing" and "jfo", which --suite refused), and an unknown name is
// refused naming the names it takes.
#include <QtTest>
#include <map>
#include <set>

#include "core/base/input_error.hpp"
#include "core/verification/all_suites.hpp"

class TestSuiteNames : public QObject {
  Q_OBJECT
 private slots:
  void everyPrintedSuiteNameSelectsItsRows() {
    const auto all = filmdyn::verification::RunSuites({});
    std::map<std::string, std::size_t> count;
    for (const auto& row : all) ++count[row.suite];
    QVERIFY(count.size() >= 6);
    std::size_t total = 0;
    for (const auto& [name, n] : count) {
      const auto rows = filmdyn::verification::RunSuites({name});
      qInfo("--suite %s: %zu rows", name.c_str(), rows.size());
      std::size_t own = 0;
      for (const auto& row : rows) own += row.suite == name;
      QCOMPARE(own, n);  // all of that name's rows
      total += n;
    }
    QCOMPARE(total, all.size());
    // A group alone: only its rows; with its suite: the suite once.
    const auto jfo = filmdyn::verification::RunSuites({"jfo"});
    QVERIFY(!jfo.empty());
    for (const auto& row : jfo) QCOMPARE(row.suite, std::string("jfo"));
    QCOMPARE(filmdyn::verification::RunSuites({"jfo", "lubrication"}).size(),
             filmdyn::verification::RunSuites({"lubrication"}).size());
  }

  void anUnknownNameListsTheNames() {
    try {
      filmdyn::verification::RunSuites({"bearings"});
      QFAIL("accepted");
    } catch (const filmdyn::InputError& e) {
      const QString text = QString::fromUtf8(e.what());
      QVERIFY2(text.startsWith("--suite = bearings: unknown suite; allowed: lubrication, ") &&
                   text.contains("bearing (of lubrication), jfo (of lubrication)"),
               qPrintable(text));
    }
  }
};

QTEST_GUILESS_MAIN(TestSuiteNames)
#include "test_suite_names.moc"
