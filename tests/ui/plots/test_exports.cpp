// Every export writes a valid file: each standard plot as PNG, SVG and PDF after a real run,
// results.csv with the header of docs/outputs.md and one row per output step. (The field files:
// tests/core/io/test_field_output.cpp and tests/ui/run/test_output_path.cpp.)
#include <QAction>
#include <QFile>
#include <QImage>
#include <QSettings>
#include <QStandardPaths>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QtTest>
#include <atomic>
#include <memory>
#include <stdexcept>

#include "tests/ui/answer_message_box.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/main_window.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/run/run_controller.hpp"
#include "ui/runs/run_table.hpp"

using filmdyn::ui::MainWindow;
using filmdyn::ui::RunHandle;

class TestExports : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_exports");
    QSettings().clear();
  }

  void everyPlotAndResultsExportWriteValidFiles() {
    MainWindow window;
    auto c = window.document()->engineCase();
    filmdyn::ui::ApplyRunModel(c, "ideal");
    c.solver.output_interval = 2.0 * M_PI / 180.0;
    window.document()->edit(c, "ideal");
    QSignalSpy finished(window.runController(), &filmdyn::ui::RunController::runFinished);
    window.runAction()->trigger();
    QVERIFY(finished.wait(120000));
    const RunHandle run = finished.first().first().value<RunHandle>();
    QCOMPARE(run->status(), filmdyn::ui::RunStatus::kFinished);

    QTemporaryDir dir;
    QString error;
    QVERIFY2(window.exportAllPlots(dir.path(), {"png", "svg", "pdf"}, &error), qPrintable(error));
    const int charts = window.plotPanel()->chartCount();
    QVERIFY(charts >= 10);
    for (int i = 0; i < charts; ++i) {
      const QString base = dir.filePath(window.plotPanel()->chartId(i));
      const QImage png(base + ".png");
      QVERIFY2(!png.isNull(), qPrintable(base + ".png"));
      QCOMPARE(png.size(), QSize(1920, 1200));  // 960 x 600 at 2x
      QSvgRenderer svg(base + ".svg");
      QVERIFY2(svg.isValid(), qPrintable(base + ".svg"));
      QFile pdf(base + ".pdf");
      QVERIFY(pdf.open(QIODevice::ReadOnly));
      const QByteArray bytes = pdf.readAll();
      QVERIFY2(bytes.startsWith("%PDF-") && bytes.trimmed().endsWith("%%EOF"),
               qPrintable(base + ".pdf"));
      QVERIFY(bytes.size() > 2000);
    }
    // A plot with data is not blank: the big-end force plot's PNG has many colours.
    {
      const QImage png(dir.filePath("bigend_forces.png"));
      QSet<QRgb> colours;
      for (int y = 0; y < png.height(); y += 3) {
        for (int x = 0; x < png.width(); x += 3) colours.insert(png.pixel(x, y));
      }
      QVERIFY(colours.size() > 20);
    }

    const QString csv = dir.filePath("results.csv");
    QVERIFY2(window.exportResultsCsv(run, csv, &error), qPrintable(error));
    QFile file(csv);
    QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(lines.size(), 1 + 360);
    const QStringList header = lines.first().split(',');
    // Core's results.csv (what `filmdyn run` writes): the 19 fixed columns first, in order.
    QVERIFY(header.size() >= filmdyn::ui::kColumnCount);
    for (int i = 0; i < filmdyn::ui::kColumnCount; ++i) {
      QCOMPARE(header[i], QString(filmdyn::ui::kColumnHeaders[size_t(i)]));
    }
    const QStringList row = lines[10].split(',');
    QCOMPARE(row.size(), header.size());
    QCOMPARE(row[0].toDouble(), 18.0);  // 2 °CA steps
    bool ok = false;
    row[header.indexOf("gas_force[N]")].toDouble(&ok);
    QVERIFY(ok);
    QVERIFY(row[header.indexOf("skirt_moft[m]")].isEmpty());  // the ideal model has no film

    // The same results in display units: same rows and columns, headers in the plots' units,
    // values scaled (N → kN, m → mm, rad → deg), empty cells kept.
    const QString csv_display = dir.filePath("results-display.csv");
    QVERIFY2(window.exportResultsCsv(run, csv_display, &error, true), qPrintable(error));
    QFile display_file(csv_display);
    QVERIFY(display_file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList display_lines =
        QString::fromUtf8(display_file.readAll()).split('\n', Qt::SkipEmptyParts);
    QCOMPARE(display_lines.size(), lines.size());
    const QStringList display_header = display_lines.first().split(',');
    QCOMPARE(display_header.size(), header.size());
    QVERIFY(display_header.contains("gas_force[kN]") && display_header.contains("skirt_moft[um]"));
    QVERIFY(display_header.contains("rod_angle[deg]") && display_header.contains("time[ms]"));
    const QStringList display_row = display_lines[10].split(',');
    const double gas_n = row[header.indexOf("gas_force[N]")].toDouble();
    QVERIFY(std::abs(display_row[display_header.indexOf("gas_force[kN]")].toDouble() -
                     gas_n * 1e-3) <= 1e-9 * std::max(1.0, std::abs(gas_n)));
    const double rod = row[header.indexOf("rod_angle[rad]")].toDouble();
    QVERIFY(std::abs(display_row[display_header.indexOf("rod_angle[deg]")].toDouble() -
                     rod * 180 / M_PI) < 1e-8);
    QVERIFY(display_row[display_header.indexOf("skirt_moft[um]")].isEmpty());

    // The whole run folder as `filmdyn run --out` writes it.
    const QString folder = dir.filePath("run");
    QVERIFY2(window.exportRunFolder(run, folder, &error), qPrintable(error));
    QVERIFY(QFile::exists(folder + "/results.csv"));
    QFile summary(folder + "/summary.json");
    QVERIFY(summary.open(QIODevice::ReadOnly));
    QVERIFY(summary.readAll().contains("\"model\""));
    summary.close();
    // Into a folder holding a run: refused unless replacing is asked (the user's files there
    // were overwritten or mixed with the new run's); replacing keeps the user's other files.
    QFile mine(folder + "/my-notes.txt");
    QVERIFY(mine.open(QIODevice::WriteOnly));
    mine.write("kept");
    mine.close();
    QVERIFY(!window.exportRunFolder(run, folder, &error));
    QVERIFY2(error.contains(folder) && error.contains("earlier run"), qPrintable(error));
    QVERIFY2(window.exportRunFolder(run, folder, &error, true), qPrintable(error));
    QVERIFY(QFile::exists(folder + "/results.csv"));
    QVERIFY(QFile::exists(folder + "/my-notes.txt"));
  }

  // The run-folder and fields exports write on a worker thread: while a write is under way the
  // window handles its events, a second export waits, and the end is reported (a failure in a
  // message box). The writers here hold until released (at most 20 s: an export written on the
  // GUI thread returns only after that, and the test fails at its first check).
  void runFolderAndFieldsExportsLeaveTheWindowResponsive() {
    MainWindow window;
    auto entered = std::make_shared<std::atomic<int>>(0);
    auto release = std::make_shared<std::atomic<bool>>(false);
    const auto hold = [entered, release] {
      ++*entered;
      for (int i = 0; i < 2000 && !*release; ++i) QThread::msleep(10);
    };
    window.runController()->setBackend([hold](const filmdyn::ui::RunRequest&,
                                              const std::atomic<bool>&,
                                              filmdyn::ui::RunSink& sink) {
      filmdyn::ui::RunWriters writers;
      writers.folder = [hold](const std::string& dir) {
        hold();
        QFile file(QString::fromStdString(dir) + "/results.csv");
        if (!file.open(QIODevice::WriteOnly)) throw std::runtime_error("cannot write");
      };
      writers.fields = [hold](const std::string&) {
        hold();
        throw std::runtime_error("no room left on the device");
      };
      sink.SetWriters(std::move(writers));
    });
    QSignalSpy finished(window.runController(), &filmdyn::ui::RunController::runFinished);
    window.runAction()->trigger();
    QVERIFY(finished.wait(30000));
    const RunHandle run = finished.first().first().value<RunHandle>();
    QTemporaryDir dir;
    QSignalSpy exported(&window, &MainWindow::exportFinished);

    window.startRunFolderExport(run, dir.path(), false);
    QVERIFY(window.isExporting());
    QTRY_COMPARE_WITH_TIMEOUT(entered->load(), 1, 10000);
    QVERIFY(exported.isEmpty());
    window.startFieldsExport(run, dir.path());  // waits for the one under way: not started
    QTest::qWait(100);
    QCOMPARE(entered->load(), 1);
    *release = true;
    QVERIFY(exported.wait(10000));
    QVERIFY(!window.isExporting());
    QCOMPARE(exported.first().at(0).toBool(), true);
    QVERIFY2(exported.first().at(1).toString().contains(dir.path()),
             qPrintable(exported.first().at(1).toString()));
    QVERIFY(QFile::exists(dir.filePath("results.csv")));

    // A failing export ends in a message box that says why.
    *release = false;
    exported.clear();
    window.startFieldsExport(run, dir.path());
    QVERIFY(window.isExporting());
    QTRY_COMPARE_WITH_TIMEOUT(entered->load(), 2, 10000);
    QString title, text;
    filmdyn::test::AnswerNextMessageBox(QMessageBox::Ok, &title, &text);
    *release = true;
    QVERIFY(exported.wait(10000));
    QCOMPARE(exported.first().at(0).toBool(), false);
    QTRY_VERIFY_WITH_TIMEOUT(!title.isEmpty(), 10000);
    QCOMPARE(title, QString("Export failed"));
    QVERIFY2(text.contains("no room left"), qPrintable(text));
  }
};

QTEST_MAIN(TestExports)
#include "test_exports.moc"
