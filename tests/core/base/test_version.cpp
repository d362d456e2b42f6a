// The engine reports the version CMake set, and core builds and links without Qt (the test links
// core + QtTest only, as every core test does).
#include <QtTest>

#include "core/base/version.hpp"

class TestVersion : public QObject {
  Q_OBJECT
 private slots:
  void versionMatchesProject() { QCOMPARE(QString::fromUtf8(filmdyn::Version().data()), QString(FILMDYN_VERSION)); }
};

QTEST_GUILESS_MAIN(TestVersion)
#include "test_version.moc"
