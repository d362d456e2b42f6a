#include "ui/case_editor/case_editor.hpp"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineSeries>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ui/case_editor/array_table_model.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/choice_delegate.hpp"
#include "ui/case_editor/parameter_table_model.hpp"
#include "ui/case_editor/pressure_csv.hpp"
#include "ui/case_editor/skirt_calculator_panel.hpp"

namespace filmdyn::ui {

namespace {

QTableView* MakeTable(QAbstractItemModel* model, QWidget* parent) {
  auto* table = new QTableView(parent);
  table->setModel(model);
  table->setAlternatingRowColors(true);
  table->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                         QAbstractItemView::AnyKeyPressed | QAbstractItemView::SelectedClicked);
  table->horizontalHeader()->setStretchLastSection(true);
  table->verticalHeader()->setDefaultSectionSize(22);
  return table;
}

QChart* MakeChart(const QString& x_title, const QString& y_title) {
  auto* chart = new QChart;
  chart->legend()->hide();
  chart->setMargins(QMargins(4, 4, 4, 4));
  auto* x = new QValueAxis;
  auto* y = new QValueAxis;
  x->setTitleText(x_title);
  y->setTitleText(y_title);
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  return chart;
}

void FitAxes(QChart* chart, double x0, double x1, double y0, double y1) {
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!(y1 > y0)) y1 = y0 + 1;
  const double pad = 0.05 * (y1 - y0);
  chart->axes(Qt::Horizontal).first()->setRange(x0, x1);
  chart->axes(Qt::Vertical).first()->setRange(y0 - pad, y1 + pad);
}

}  // namespace

CaseEditor::CaseEditor(CaseDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  tabs_ = new QTabWidget(this);
  tabs_->setObjectName("case_tabs");
  layout->addWidget(tabs_);
  for (CaseGroup g :
       {CaseGroup::kOperating, CaseGroup::kGeometry, CaseGroup::kMasses, CaseGroup::kSkirt,
        CaseGroup::kBigEnd, CaseGroup::kLubricant, CaseGroup::kSolver}) {
    QWidget* page = g == CaseGroup::kSkirt ? makeProfilePage() : makeParameterPage(g);
    tabs_->addTab(page, CaseGroupTitle(g));
  }
  tabs_->addTab(makePressurePage(), tr("Cylinder pressure"));
  connect(document_, &CaseDocument::caseChanged, this, [this] {
    updateCurveSelector();
    const QString key = RunModelKey(document_->engineCase());
    const int index = model_combo_->findData(key);
    if (index != model_combo_->currentIndex()) {
      QSignalBlocker block(model_combo_);
      model_combo_->setCurrentIndex(index);
    }
    updateCharts();
  });
  updateCurveSelector();
  updateCharts();
}

QWidget* CaseEditor::makeParameterPage(CaseGroup group) {
  auto* page = new QWidget(this);
  auto* layout = new QVBoxLayout(page);
  if (group == CaseGroup::kOperating) {
    auto* form = new QFormLayout;
    model_combo_ = new QComboBox(page);
    model_combo_->setObjectName("model_selector");
    for (const RunModel& m : RunModels()) model_combo_->addItem(m.title, m.key);
    model_combo_->setCurrentIndex(model_combo_->findData(RunModelKey(document_->engineCase())));
    model_combo_->setToolTip(
        tr("<qt>Which joints run on an oil film: <b>Skirt-LBRBE</b> the piston skirt and the "
           "big-end bearing (LBRBE: lubricated big-end bearing); <b>Only-Skirt</b> the skirt "
           "only; <b>Only-LBRBE</b> the big end only; <b>Ideal</b> neither (pure kinematics, "
           "no clearances).</qt>"));
    connect(model_combo_, &QComboBox::activated, this, [this](int index) {
      engine::EngineCase next = document_->engineCase();
      ApplyRunModel(next, model_combo_->itemData(index).toString());
      document_->edit(next, tr("Change model to %1").arg(model_combo_->itemText(index)));
    });
    form->addRow(tr("Model"), model_combo_);
    layout->addLayout(form);
  }
  auto* model = new ParameterTableModel(document_, group, page);
  auto* table = MakeTable(model, page);
  table->setObjectName(QString("parameters_%1").arg(int(group)));
  table->horizontalHeader()->setSectionResizeMode(ParameterTableModel::kQuantity,
                                                  QHeaderView::ResizeToContents);
  table->setColumnWidth(ParameterTableModel::kValue, 110);
  table->setColumnWidth(ParameterTableModel::kUnit, 60);
  // Choices (core's names): a combo box in the value cell, always open, the column wide enough
  // for the longest name.
  table->setItemDelegateForColumn(ParameterTableModel::kValue, new ChoiceDelegate(table));
  int value_width = table->columnWidth(ParameterTableModel::kValue);
  for (int row = 0; row < model->rowCount(); ++row) {
    const QModelIndex value = model->index(row, ParameterTableModel::kValue);
    if (!ChoiceDelegate::IsChoice(value)) continue;
    table->openPersistentEditor(value);
    if (QWidget* editor = table->indexWidget(value))
      value_width = std::max(value_width, editor->sizeHint().width() + 2);
  }
  table->setColumnWidth(ParameterTableModel::kValue, value_width);
  connect(table->selectionModel(), &QItemSelectionModel::currentChanged, this,
          [this](const QModelIndex& current) {
            const QString tip = current.data(Qt::ToolTipRole).toString();
            if (current.data(Qt::BackgroundRole).isValid()) emit statusMessage(tip);
          });
  models_[group] = model;
  tables_[group] = table;
  layout->addWidget(table);
  return page;
}

QWidget* CaseEditor::makeArrayBlock(const QString& title, ArrayTableModel* model,
                                    const QString& table_name, QChart* chart, QWidget* parent) {
  auto* block = new QWidget(parent);
  auto* layout = new QVBoxLayout(block);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel(title, block));
  auto* tables = new QSplitter(Qt::Horizontal, block);
  QTableView* table = MakeTable(model, tables);
  table->setObjectName(table_name);
  auto* view = new QChartView(chart, tables);
  view->setRenderHint(QPainter::Antialiasing);
  tables->addWidget(table);
  tables->addWidget(view);
  tables->setStretchFactor(1, 2);
  layout->addWidget(tables, 1);
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton(tr("Insert row"), block);
  auto* remove = new QPushButton(tr("Remove row"), block);
  connect(add, &QPushButton::clicked, this, [table, model] {
    const int row =
        table->currentIndex().isValid() ? table->currentIndex().row() : model->rowCount() - 1;
    model->insertRowAfter(row);
  });
  connect(remove, &QPushButton::clicked, this, [table, model] {
    if (table->currentIndex().isValid()) model->removeRowAt(table->currentIndex().row());
  });
  buttons->addWidget(add);
  buttons->addWidget(remove);
  buttons->addStretch();
  layout->addLayout(buttons);
  return block;
}

QWidget* CaseEditor::makeProfilePage() {
  // Above: the skirt's inputs; below: the steady calculator on this case's skirt.
  auto* page = new QSplitter(Qt::Vertical, this);
  page->setObjectName("skirt_page");
  auto* splitter = new QSplitter(Qt::Horizontal, page);
  splitter->addWidget(makeParameterPage(CaseGroup::kSkirt));

  // Right: the axial profile above the ovality, each as table + chart side by side.
  auto* right = new QSplitter(Qt::Vertical, splitter);
  profile_model_ = new ArrayTableModel(
      document_,
      {{tr("y [mm]"), 1e-3, [](engine::EngineCase& c) { return &c.skirt.profile_y; },
        "skirt.profile_y"},
       {tr("h [µm]"), 1e-6, [](engine::EngineCase& c) { return &c.skirt.profile_h; },
        "skirt.profile_h"}},
      [] { return std::string("skirt.profile"); }, tr("skirt profile"), this);
  profile_chart_ = MakeChart(tr("y from skirt top [mm]"), tr("profile drop h [µm]"));
  right->addWidget(makeArrayBlock(tr("<b>Skirt profile</b> (barrel drop h_skirt vs. distance "
                                     "from the skirt top)"),
                                  profile_model_, "profile_table", profile_chart_, right));
  profile_table_ = right->findChild<QTableView*>("profile_table");
  ovality_model_ = new ArrayTableModel(
      document_,
      {{tr("α [°]"), std::numbers::pi / 180.0,
        [](engine::EngineCase& c) { return &c.skirt.ovality_alpha; }, "skirt.ovality_alpha"},
       {tr("h [µm]"), 1e-6, [](engine::EngineCase& c) { return &c.skirt.ovality_h; },
        "skirt.ovality_h"}},
      [] { return std::string("skirt.ovality"); }, tr("skirt ovality"), this);
  ovality_chart_ = MakeChart(tr("α from the thrust axis [°]"), tr("ovality gap h [µm]"));
  right->addWidget(makeArrayBlock(tr("<b>Skirt ovality</b> (extra radial gap vs. angle from the "
                                     "thrust axis; no rows = round skirt)"),
                                  ovality_model_, "ovality_table", ovality_chart_, right));
  ovality_table_ = right->findChild<QTableView*>("ovality_table");
  splitter->addWidget(right);
  splitter->setStretchFactor(0, 2);
  splitter->setStretchFactor(1, 3);
  splitter->setSizes({560, 840});
  skirt_calculator_ = new SkirtCalculatorPanel(document_, page);
  page->addWidget(skirt_calculator_);
  page->setStretchFactor(0, 1);
  page->setStretchFactor(1, 1);
  return page;
}

QWidget* CaseEditor::makePressurePage() {
  auto* page = new QWidget(this);
  auto* layout = new QVBoxLayout(page);
  auto* bar = new QHBoxLayout;
  curve_combo_ = new QComboBox(page);
  curve_combo_->setObjectName("curve_selector");
  curve_combo_->setMinimumWidth(140);
  bar->addWidget(new QLabel(tr("Speed:"), page));
  bar->addWidget(curve_combo_);
  auto* add = new QPushButton(tr("Add speed…"), page);
  auto* remove = new QPushButton(tr("Remove"), page);
  auto* import = new QPushButton(tr("Import CSV…"), page);
  auto* export_csv = new QPushButton(tr("Export CSV…"), page);
  connect(add, &QPushButton::clicked, this, &CaseEditor::addPressureCurve);
  connect(remove, &QPushButton::clicked, this, &CaseEditor::removePressureCurve);
  connect(import, &QPushButton::clicked, this, [this] { importPressureCsv(); });
  connect(export_csv, &QPushButton::clicked, this, [this] { exportPressureCsv(); });
  for (QWidget* w : {static_cast<QWidget*>(add), static_cast<QWidget*>(remove),
                     static_cast<QWidget*>(import), static_cast<QWidget*>(export_csv)}) {
    bar->addWidget(w);
  }
  bar->addStretch();
  layout->addLayout(bar);
  connect(curve_combo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    current_curve_ = index;
    pressure_model_->refresh();
    updateCharts();
  });

  auto* splitter = new QSplitter(Qt::Horizontal, page);
  auto curve_array = [this](bool angle) {
    return [this, angle](engine::EngineCase& c) -> std::vector<double>* {
      if (current_curve_ < 0 || current_curve_ >= int(c.pressure_curves.size())) return nullptr;
      auto& curve = c.pressure_curves[size_t(current_curve_)];
      return angle ? &curve.crank_angle_deg : &curve.pressure;
    };
  };
  pressure_model_ = new ArrayTableModel(
      document_,
      {{tr("crank angle [°CA]"),
        1.0,
        curve_array(true),
        {},
        tr("<qt><b>Crank angle</b><p>Where in the four-stroke cycle this pressure is measured: "
           "0 to 720 °CA, 360 = firing top dead centre; strictly increasing.</p>"
           "<p style='color:#666666'>In the case file: pressure_curves[k].crank_angle_deg</p>"
           "</qt>")},
       {tr("p_cyl absolute [MPa]"),
        1e6,
        curve_array(false),
        {},
        tr("<qt><b>Cylinder pressure (absolute)</b><p>Gas pressure above the piston at this "
           "crank angle; the gas force on the piston is this minus the crankcase pressure, "
           "times the bore area.</p><p>Unit: MPa &nbsp;·&nbsp; Allowed: ≥ 0</p>"
           "<p style='color:#666666'>In the case file: pressure_curves[k].pressure (Pa)</p>"
           "</qt>")}},
      [this] { return "pressure_curves[" + std::to_string(current_curve_) + "]"; },
      tr("pressure curve"), this);
  pressure_table_ = MakeTable(pressure_model_, splitter);
  pressure_table_->setObjectName("pressure_table");
  pressure_chart_ =
      MakeChart(tr("crank angle [°CA] (360 = firing TDC)"), tr("cylinder pressure [MPa]"));
  pressure_chart_->legend()->show();
  auto* view = new QChartView(pressure_chart_, splitter);
  view->setRenderHint(QPainter::Antialiasing);
  splitter->addWidget(pressure_table_);
  splitter->addWidget(view);
  splitter->setStretchFactor(1, 2);
  layout->addWidget(splitter, 1);
  return page;
}

void CaseEditor::updateCurveSelector() {
  const auto& curves = document_->engineCase().pressure_curves;
  QStringList labels;
  for (const auto& c : curves) labels << tr("%1 rpm").arg(FormatDisplayNumber(c.rpm));
  QStringList current;
  for (int i = 0; i < curve_combo_->count(); ++i) current << curve_combo_->itemText(i);
  if (labels == current) return;
  const int keep = current_curve_;
  {
    QSignalBlocker block(curve_combo_);
    curve_combo_->clear();
    curve_combo_->addItems(labels);
    current_curve_ = labels.isEmpty() ? -1 : std::clamp(keep, 0, int(labels.size()) - 1);
    curve_combo_->setCurrentIndex(current_curve_);
  }
  pressure_model_->refresh();
}

void CaseEditor::updateCharts() {
  const engine::EngineCase& c = document_->engineCase();
  // Profile.
  {
    if (profile_chart_->series().isEmpty()) {
      auto* s = new QLineSeries;
      s->setPointsVisible(true);
      profile_chart_->addSeries(s);
      for (auto* axis : profile_chart_->axes()) s->attachAxis(axis);
    }
    auto* s = static_cast<QLineSeries*>(profile_chart_->series().first());
    QList<QPointF> points;
    double y0 = 0, y1 = 0;
    for (size_t i = 0; i < c.skirt.profile_y.size() && i < c.skirt.profile_h.size(); ++i) {
      const double h = c.skirt.profile_h[i] * 1e6;
      if (std::isfinite(h) && std::isfinite(c.skirt.profile_y[i])) {
        points << QPointF(c.skirt.profile_y[i] * 1e3, h);
        y0 = points.size() == 1 ? h : std::min(y0, h);
        y1 = points.size() == 1 ? h : std::max(y1, h);
      }
    }
    s->replace(points);
    FitAxes(profile_chart_, 0.0, c.skirt.length * 1e3, std::min(0.0, y0), y1);
  }
  // Ovality over the half skirt α ∈ [0°, 180°].
  {
    if (ovality_chart_->series().isEmpty()) {
      auto* s = new QLineSeries;
      s->setPointsVisible(true);
      ovality_chart_->addSeries(s);
      for (auto* axis : ovality_chart_->axes()) s->attachAxis(axis);
    }
    auto* s = static_cast<QLineSeries*>(ovality_chart_->series().first());
    QList<QPointF> points;
    double y1 = 0;
    const auto& alpha = c.skirt.ovality_alpha;
    const auto& gap = c.skirt.ovality_h;
    for (size_t i = 0; i < alpha.size() && i < gap.size(); ++i) {
      const double h = gap[i] * 1e6;
      const double deg = alpha[i] * 180.0 / std::numbers::pi;
      if (std::isfinite(h) && std::isfinite(deg)) {
        points << QPointF(deg, h);
        y1 = std::max(y1, h);
      }
    }
    s->replace(points);
    FitAxes(ovality_chart_, 0.0, 180.0, 0.0, y1);
  }
  // Pressure curves: one series per speed, the edited one thicker.
  {
    const auto& curves = c.pressure_curves;
    while (pressure_chart_->series().size() > qsizetype(curves.size())) {
      auto* s = pressure_chart_->series().last();
      pressure_chart_->removeSeries(s);
      delete s;
    }
    while (pressure_chart_->series().size() < qsizetype(curves.size())) {
      auto* s = new QLineSeries;
      pressure_chart_->addSeries(s);
      for (auto* axis : pressure_chart_->axes()) s->attachAxis(axis);
    }
    double p_max = 1.0;
    for (size_t i = 0; i < curves.size(); ++i) {
      auto* s = static_cast<QLineSeries*>(pressure_chart_->series()[qsizetype(i)]);
      QList<QPointF> points;
      for (size_t k = 0; k < curves[i].crank_angle_deg.size() && k < curves[i].pressure.size();
           ++k) {
        const double p = curves[i].pressure[k] * 1e-6;
        if (std::isfinite(p) && std::isfinite(curves[i].crank_angle_deg[k])) {
          points << QPointF(curves[i].crank_angle_deg[k], p);
          p_max = std::max(p_max, p);
        }
      }
      s->replace(points);
      s->setName(tr("%1 rpm").arg(FormatDisplayNumber(curves[i].rpm)));
      QPen pen = s->pen();
      pen.setWidthF(int(i) == current_curve_ ? 2.5 : 1.0);
      s->setPen(pen);
    }
    FitAxes(pressure_chart_, 0.0, 720.0, 0.0, p_max);
  }
}

void CaseEditor::addPressureCurve() {
  bool ok = false;
  const double rpm =
      QInputDialog::getDouble(this, tr("Add pressure curve"), tr("Speed [rpm]:"),
                              document_->engineCase().operating.rpm, 1, 30000, 0, &ok);
  if (!ok) return;
  engine::EngineCase next = document_->engineCase();
  engine::PressureCurveSource curve;
  curve.rpm = rpm;
  // Start from the crankcase pressure everywhere; the user types or imports the curve.
  for (int a = 0; a <= 720; a += 10) {
    curve.crank_angle_deg.push_back(a);
    curve.pressure.push_back(next.operating.crankcase_pressure);
  }
  next.pressure_curves.push_back(curve);
  current_curve_ = int(next.pressure_curves.size()) - 1;
  document_->edit(next, tr("Add pressure curve %1 rpm").arg(rpm));
  curve_combo_->setCurrentIndex(current_curve_);
}

void CaseEditor::removePressureCurve() {
  if (current_curve_ < 0) return;
  engine::EngineCase next = document_->engineCase();
  next.pressure_curves.erase(next.pressure_curves.begin() + current_curve_);
  document_->edit(next, tr("Remove pressure curve"));
}

void CaseEditor::importPressureCsv(const QString& given_path) {
  QString path = given_path;
  if (path.isEmpty()) {
    path = QFileDialog::getOpenFileName(this, tr("Import cylinder pressure"), {},
                                        tr("CSV files (*.csv *.txt);;All files (*)"));
    if (path.isEmpty()) return;
  }
  engine::EngineCase next = document_->engineCase();
  engine::PressureCurveSource curve;
  QString error;
  if (!ImportPressureCsv(path, &curve, &error)) {
    emit statusMessage(error);
    if (given_path.isEmpty()) QMessageBox::warning(this, tr("Import failed"), error);
    return;
  }
  // The speed: the selected curve's, or one read from the file name ("..._4000rpm.csv").
  double rpm = next.operating.rpm;
  if (current_curve_ >= 0) rpm = next.pressure_curves[size_t(current_curve_)].rpm;
  static const QRegularExpression rpm_re("(\\d+)\\s*rpm",
                                         QRegularExpression::CaseInsensitiveOption);
  const auto match = rpm_re.match(QFileInfo(path).fileName());
  if (match.hasMatch()) rpm = match.captured(1).toDouble();
  curve.rpm = rpm;
  int index = -1;
  for (size_t i = 0; i < next.pressure_curves.size(); ++i) {
    if (next.pressure_curves[i].rpm == rpm) index = int(i);
  }
  if (index < 0) {
    next.pressure_curves.push_back(curve);
    index = int(next.pressure_curves.size()) - 1;
  } else {
    next.pressure_curves[size_t(index)] = curve;
  }
  current_curve_ = index;
  document_->edit(next, tr("Import pressure curve %1").arg(QFileInfo(path).fileName()));
  curve_combo_->setCurrentIndex(index);
  emit statusMessage(
      tr("Imported %1 points at %2 rpm from %3").arg(curve.pressure.size()).arg(rpm).arg(path));
}

void CaseEditor::exportPressureCsv(const QString& given_path) {
  if (current_curve_ < 0) return;
  const auto& curve = document_->engineCase().pressure_curves[size_t(current_curve_)];
  QString path = given_path;
  if (path.isEmpty()) {
    path = QFileDialog::getSaveFileName(this, tr("Export cylinder pressure"),
                                        QString("pressure_%1rpm.csv").arg(curve.rpm),
                                        tr("CSV files (*.csv)"));
    if (path.isEmpty()) return;
  }
  QString error;
  if (!ExportPressureCsv(curve, path, &error)) {
    emit statusMessage(error);
    if (given_path.isEmpty()) QMessageBox::warning(this, tr("Export failed"), error);
    return;
  }
  emit statusMessage(tr("Wrote %1").arg(path));
}

}  // namespace filmdyn::ui
