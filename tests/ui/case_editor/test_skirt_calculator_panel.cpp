// The steady skirt calculator on the skirt tab, driven through its real widgets in the main
// window: typing a state shows the same numbers as the core calculator (every quantity of the
// table), a load finds the state that carries it, a state into the liner and a load beyond the
// capacity show the core's message naming the input, editing the case recomputes, the film map
// shows the chosen field, and the window stays responsive while it computes. With
// FILMDYN_SCREENSHOT_DIR set, the tab is pictured.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QtTest>
#include <cmath>

#include "core/engine/film_joints.hpp"
#include "core/lubrication/skirt_calculator.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_editor.hpp"
#include "ui/case_editor/skirt_calculator_panel.hpp"
#include "ui/main_window.hpp"

using namespace filmdyn;
using filmdyn::ui::MainWindow;
using filmdyn::ui::SkirtCalculatorPanel;

namespace {

// Types a value into a spin box like a user (select all, type, Enter) and waits for the result.
void Type(SkirtCalculatorPanel* panel, const std::string& key, const QString& text) {
  QDoubleSpinBox* box = panel->input(key);
  box->setFocus();
  box->selectAll();
  QTest::keyClicks(box, text);
  QTest::keyClick(box, Qt::Key_Return);
}

void WaitForResult(SkirtCalculatorPanel* panel) {
  QTRY_VERIFY_WITH_TIMEOUT(!panel->busy() && panel->last().has_value(), 20000);
}

double Shown(SkirtCalculatorPanel* panel, const QString& key) {
  QTableWidget* table = panel->resultTable();
  for (int r = 0; r < table->rowCount(); ++r) {
    if (table->item(r, 0)->data(Qt::UserRole).toString() == key) {
      return table->item(r, 1)->data(Qt::UserRole).toDouble();
    }
  }
  return std::nan("");
}

}  // namespace

class TestSkirtCalculatorPanel : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("FilmDynTest");
    QCoreApplication::setApplicationName("test_skirt_calculator_panel");
    QSettings().clear();
  }

  void stateLoadErrorsAndCaseEdits() {
    MainWindow window;
    window.resize(1600, 1000);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    auto* tabs = window.caseEditor()->findChild<QTabWidget*>("case_tabs");
    tabs->setCurrentIndex(3);  // Skirt
    SkirtCalculatorPanel* panel = window.caseEditor()->skirtCalculator();
    QVERIFY(panel != nullptr && panel->isVisible());
    WaitForResult(panel);  // the default state is computed on opening

    // A state typed in display units: the table holds what the core calculator says.
    Type(panel, "e0", "12");
    Type(panel, "tilt", "-0.3");
    Type(panel, "speed", "-9");
    WaitForResult(panel);
    QVERIFY2(panel->last()->ok, qPrintable(panel->statusLabel()->text()));
    lubrication::SkirtCalculator calc(engine::SkirtConfigFromCase(window.document()->engineCase()));
    lubrication::SkirtState s;
    s.e0 = 12e-6, s.gamma = -0.3e-3, s.piston_velocity = -9.0;
    const lubrication::SkirtPoint direct = calc.AtState(s);
    QCOMPARE(Shown(panel, "e0"), 12e-6);
    QCOMPARE(Shown(panel, "normal_force"), direct.film.lateral_force);
    QCOMPARE(Shown(panel, "moment_about_pin"), direct.film.moment_about_pin);
    QCOMPARE(Shown(panel, "moft"), direct.film.moft);
    QCOMPARE(panel->resultTable()->rowCount(), 20);  // io::SkirtQuantities()

    // The load of that state, in load mode: the calculator finds the state again.
    panel->modeSelector()->setCurrentIndex(1);
    QVERIFY(!panel->input("e0")->isEnabled() && panel->input("side_force")->isEnabled());
    Type(panel, "side_force", QString::number(-direct.film.lateral_force, 'f', 1));
    Type(panel, "moment", QString::number(-direct.film.moment_about_pin, 'f', 3));
    WaitForResult(panel);
    QVERIFY2(panel->last()->ok, qPrintable(panel->statusLabel()->text()));
    QVERIFY2(panel->statusLabel()->text().startsWith("Equilibrium found"),
             qPrintable(panel->statusLabel()->text()));
    QVERIFY2(std::abs(Shown(panel, "e0") - 12e-6) < 0.01e-6,
             qPrintable(QString::number(Shown(panel, "e0"))));

    // Beyond the capacity: the core's message, naming the input as labelled.
    Type(panel, "side_force", "5000000");
    WaitForResult(panel);
    QVERIFY(!panel->last()->ok);
    QVERIFY2(panel->statusLabel()->text().startsWith("Side force = 5e+06 N: beyond what the skirt "
                                                     "carries at Speed = -9 m/s"),
             qPrintable(panel->statusLabel()->text()));
    // The results still shown are the state before: greyed, table and map, until inputs give
    // a result again.
    QVERIFY(!panel->resultTable()->isEnabled() && !panel->filmMap()->isEnabled());

    // A state into the liner.
    panel->modeSelector()->setCurrentIndex(0);
    Type(panel, "e0", "40");
    WaitForResult(panel);
    QVERIFY(!panel->last()->ok);
    // Values in the units the inputs are typed in (µm, mrad), not SI.
    const QString into = panel->statusLabel()->text();
    QVERIFY2(into.startsWith("e0 = 40 µm: puts the skirt into the liner"), qPrintable(into));
    QVERIFY2(QRegularExpression("at Tilt = -?[0-9.]+ mrad the film is positive for -?[0-9.]+ µm < "
                                "e0 < [0-9.]+ µm$")
                 .match(into)
                 .hasMatch(),
             qPrintable(into));

    // Editing the case recomputes: twice the viscosity, twice the hydrodynamic force.
    Type(panel, "e0", "10");
    Type(panel, "tilt", "0");
    Type(panel, "speed", "10");
    WaitForResult(panel);
    QVERIFY(panel->resultTable()->isEnabled() && panel->filmMap()->isEnabled());
    const double before = Shown(panel, "normal_force");
    engine::EngineCase doubled = window.document()->engineCase();
    doubled.lubricant.viscosity *= 2.0;
    window.document()->edit(doubled, "double the viscosity");
    QTRY_VERIFY_WITH_TIMEOUT(panel->busy(), 2000);
    QVERIFY(!panel->resultTable()->isEnabled());  // the old case's results, while computing
    WaitForResult(panel);
    QVERIFY2(std::abs(Shown(panel, "normal_force") / before - 2.0) < 1e-6,
             qPrintable(QString("%1 vs %2").arg(Shown(panel, "normal_force")).arg(before)));

    // The map shows the chosen field: the film thickness's smallest value is the MOFT.
    panel->mapSelector()->setCurrentIndex(1);
    const auto& values = panel->filmMap()->data().values;
    QVERIFY(!values.empty());
    QVERIFY(std::abs(*std::min_element(values.begin(), values.end()) - Shown(panel, "moft") * 1e6) <
            1e-9);
    QVERIFY(panel->filmMap()->data().value_title.contains("thickness"));
    panel->mapSelector()->setCurrentIndex(0);

    if (const QString dir = qEnvironmentVariable("FILMDYN_SCREENSHOT_DIR"); !dir.isEmpty()) {
      // The calculator's main use, the equilibrium under a side force and a moment (not the
      // 5 MN left from the capacity check above), with no input's text selected.
      panel->modeSelector()->setCurrentIndex(1);
      Type(panel, "side_force", QString::number(-direct.film.lateral_force, 'f', 1));
      Type(panel, "moment", QString::number(-direct.film.moment_about_pin, 'f', 3));
      WaitForResult(panel);
      QVERIFY2(panel->last()->ok, qPrintable(panel->statusLabel()->text()));
      panel->statusLabel()->setFocus();
      for (QLineEdit* edit : panel->findChildren<QLineEdit*>()) edit->deselect();
      QTest::qWait(100);
      QVERIFY(window.grab().save(dir + "/case_skirt_calculator.png"));
    }
  }
};

QTEST_MAIN(TestSkirtCalculatorPanel)
#include "test_skirt_calculator_panel.moc"
