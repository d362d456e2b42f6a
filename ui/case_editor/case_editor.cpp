#include "ui/case_editor/case_editor.hpp"

#include <QAction>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGraphicsLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineSeries>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

#include "ui/case_editor/array_table_model.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/choice_delegate.hpp"
#include "ui/case_editor/list_csv.hpp"
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

// Gives an array table the width of its row numbers, every (bold, when current) header and the
// scroll bar, its columns sharing it; returns that width.
int FitWidthToHeaders(QTableView* table) {
  table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  const QFontMetrics metrics = table->horizontalHeader()->fontMetrics();
  int width = metrics.horizontalAdvance("0000") + 12 + 2 * table->frameWidth() +
              table->verticalScrollBar()->sizeHint().width();
  for (int col = 0; col < table->model()->columnCount(); ++col) {
    const QString header = table->model()->headerData(col, Qt::Horizontal).toString();
    width += std::max(80, metrics.horizontalAdvance(header) + 24);
  }
  table->setMinimumWidth(width);
  return width;
}

QChart* MakeChart(const QString& x_title, const QString& y_title) {
  auto* chart = new QChart;
  chart->legend()->hide();
  chart->setMargins(QMargins(4, 4, 4, 4));
  chart->layout()->setContentsMargins(0, 0, 0, 0);  // the plot area's height is the y title's room
  chart->setBackgroundRoundness(0);
  auto* x = new QValueAxis;
  auto* y = new QValueAxis;
  x->setTitleText(x_title);
  y->setTitleText(y_title);
  // Titles a point smaller than the chart's default: a short chart's y title ("radial drop h
  // [µm]") fits its height whole.
  for (QValueAxis* axis : {x, y}) {
    QFont font = axis->titleFont();
    font.setPointSizeF(std::max(7.0, font.pointSizeF() - 1.0));
    axis->setTitleFont(font);
  }
  x->setLabelFormat("%g");  // "135", not "135.0": room in a narrow chart
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  return chart;
}

void FitAxes(QChart* chart, double x0, double x1, double y0, double y1) {
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!(y1 > y0)) y1 = y0 + 1;
  const double pad = 0.05 * (y1 - y0);
  chart->axes(Qt::Horizontal).first()->setRange(x0, x1);
  // Round ticks (a step of 1, 2, 2.5 or 5 × 10^k, at most six), a scale of values ≥ 0 from 0
  // itself (its first tick exactly 0), labels with as many decimals as the step needs.
  const double lo = y0 >= 0.0 ? std::max(0.0, y0 - pad) : y0 - pad;
  const double hi = y1 + pad;
  const double raw = (hi - lo) / 5.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10.0 * magnitude;
  for (double m : {1.0, 2.0, 2.5, 5.0}) {
    if (m * magnitude >= raw * (1.0 - 1e-9)) {
      step = m * magnitude;
      break;
    }
  }
  const double first = std::floor(lo / step + 1e-9) * step;
  const double last = std::ceil(hi / step - 1e-9) * step;
  auto* y = static_cast<QValueAxis*>(chart->axes(Qt::Vertical).first());
  if (!std::isfinite(first) || !std::isfinite(last) || !(last > first)) {
    y->setRange(lo, hi);  // values near the double range: no round scale
    return;
  }
  y->setRange(first, last);
  y->setTickCount(int(std::lround((last - first) / step)) + 1);
  int decimals = 0;
  while (decimals < 6 && std::abs(step * std::pow(10.0, decimals) -
                                  std::round(step * std::pow(10.0, decimals))) > 1e-6) {
    ++decimals;
  }
  y->setLabelFormat(QString("%.%1f").arg(decimals));
}

QString FieldLabel(const char* path) {
  const engine::CaseField* field = engine::FindCaseField(path);
  return field ? QString::fromStdString(field->label).toHtmlEscaped() : QString();
}

// What the editor says beside a list table's title; the fields' own words are in the tooltips.
QString ListNote(const CaseListTable& table) {
  const std::string& key = table.key;
  if (key == "skirt.profile_y") {
    return CaseEditor::tr("barrel drop vs. distance from the skirt top");
  }
  if (key == "skirt.ovality_alpha") {
    return CaseEditor::tr("extra radial gap vs. angle from the thrust axis; no rows = round skirt");
  }
  if (key == "skirt.oil_film_positions") {
    return CaseEditor::tr("feeds a starved skirt; no rows = the constant <i>%1</i>")
        .arg(FieldLabel("skirt.oil_film"));
  }
  if (key == "big_end.supply_pressure_angles") {
    return CaseEditor::tr("over the cycle; no rows = the constant <i>%1</i>")
        .arg(FieldLabel("big_end.oil_feed_pressure"));
  }
  if (key == "big_end.supply_hole_angles") {
    return CaseEditor::tr("one row per hole");
  }
  return {};
}

// A list chart's horizontal extent in display units: the skirt's length for its profile, the
// field's own range where that is the natural frame (the ovality's half circle, the supply
// curve's cycle); otherwise (false) the data's.
bool ListChartXRange(const CaseListTable& table, const engine::EngineCase& c, double* x0,
                     double* x1) {
  const engine::CaseField& x = *table.columns.front();
  if (table.key == "skirt.profile_y") {
    *x0 = 0.0;
    *x1 = c.skirt.length / x.display_scale;
    return true;
  }
  if (table.key == "skirt.ovality_alpha" || table.key == "big_end.supply_pressure_angles") {
    *x0 = x.range.lo / x.display_scale;
    *x1 = x.range.hi / x.display_scale;
    return std::isfinite(x.range.lo) && std::isfinite(x.range.hi);
  }
  return false;
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
  connect(model, &ParameterTableModel::editRefused, this, &CaseEditor::statusMessage);
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
  // The group's number lists below its scalar rows, the rows keeping the room they need.
  if (QWidget* lists = makeListRow(group, page)) {
    auto* split = new QSplitter(Qt::Vertical, page);
    split->setObjectName(QString("parameters_split_%1").arg(int(group)));
    split->setChildrenCollapsible(false);
    table->setParent(split);
    split->addWidget(table);
    lists->setParent(split);
    // Room for the charts' tick labels and titles (below ~280 px Qt Charts elides them to
    // "…"); a long list of rows scrolls instead.
    lists->setMinimumHeight(280);
    split->addWidget(lists);
    const int rows_height = table->horizontalHeader()->sizeHint().height() +
                            model->rowCount() * table->verticalHeader()->defaultSectionSize() +
                            2 * table->frameWidth();
    split->setSizes({rows_height, std::max(240, 700 - rows_height)});
    split->setStretchFactor(0, 0);
    split->setStretchFactor(1, 1);
    layout->addWidget(split, 1);
  } else {
    layout->addWidget(table);
  }
  return page;
}

QWidget* CaseEditor::makeListBlock(const CaseListTable& list, QWidget* parent) {
  ListBlock block;
  block.table = &list;
  block.model = new ArrayTableModel(document_, list, this);
  const QString key = QString::fromStdString(list.key);
  auto* widget = new QWidget(parent);
  auto* layout = new QVBoxLayout(widget);
  layout->setContentsMargins(0, 0, 0, 0);
  QString title = "<b>" + list.title.toHtmlEscaped() + "</b>";
  if (const QString note = ListNote(list); !note.isEmpty()) title += " (" + note + ")";
  auto* heading = new QLabel(title, widget);
  heading->setWordWrap(true);
  layout->addWidget(heading);
  // Its columns' "assumed" notes, and why no run reads it now: a line each, in grey, outside the
  // part that is disabled so that they stay readable.
  block.assumed = new QLabel(widget);
  block.assumed->setObjectName(key + "_assumed");
  block.assumed->setTextFormat(Qt::PlainText);
  block.assumed->setWordWrap(true);
  block.assumed->setStyleSheet("color: #666666;");
  layout->addWidget(block.assumed);
  block.hint = new QLabel(widget);
  block.hint->setObjectName(key + "_hint");
  block.hint->setTextFormat(Qt::PlainText);
  block.hint->setWordWrap(true);
  block.hint->setStyleSheet("color: #666666; font-style: italic;");
  layout->addWidget(block.hint);
  block.body = new QWidget(widget);
  block.body->setObjectName(key + "_body");
  auto* body = new QVBoxLayout(block.body);
  body->setContentsMargins(0, 0, 0, 0);
  auto* tables = new QSplitter(Qt::Horizontal, block.body);
  tables->setChildrenCollapsible(false);
  block.view = MakeTable(block.model, tables);
  block.view->setObjectName(key + "_table");
  const int table_width = FitWidthToHeaders(block.view);
  tables->addWidget(block.view);
  if (list.columns.size() == 2) {
    const QString x = block.model->headerData(0, Qt::Horizontal, Qt::DisplayRole).toString();
    const QString y = block.model->headerData(1, Qt::Horizontal, Qt::DisplayRole).toString();
    block.chart = MakeChart(x, y);
    auto* series = new QLineSeries;
    series->setPointsVisible(true);
    block.chart->addSeries(series);
    for (auto* axis : block.chart->axes()) series->attachAxis(axis);
    auto* view = new QChartView(block.chart, tables);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumWidth(160);
    tables->addWidget(view);
    // The table as narrow as its headers allow, the chart taking the rest.
    tables->setStretchFactor(0, 0);
    tables->setStretchFactor(1, 1);
    tables->setSizes({table_width, 4 * table_width});
  }
  body->addWidget(tables, 1);
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton(tr("Insert row"), block.body);
  auto* remove = new QPushButton(tr("Remove row"), block.body);
  auto* import = new QPushButton(tr("Import CSV…"), block.body);
  auto* export_csv = new QPushButton(tr("Export CSV…"), block.body);
  add->setObjectName(key + "_insert");
  remove->setObjectName(key + "_remove");
  import->setObjectName(key + "_import");
  export_csv->setObjectName(key + "_export");
  const QString header = QString::fromStdString(ListCsvHeader(list)).toHtmlEscaped();
  import->setToolTip(tr("<qt>Replace all rows by those of a CSV file (one undoable edit): a "
                        "header <tt>%1</tt>, then one row per line in the units of the header; "
                        "lines starting with # are comments.</qt>")
                         .arg(header));
  export_csv->setToolTip(tr("<qt>Write the rows to a CSV file: the header <tt>%1</tt>, then one "
                            "row per line in the units of the header.</qt>")
                             .arg(header));
  ArrayTableModel* model = block.model;
  QTableView* table = block.view;
  const std::string path = list.key;
  auto insert_row = [table, model] {
    const int row =
        table->currentIndex().isValid() ? table->currentIndex().row() : model->rowCount() - 1;
    model->insertRowAfter(row);
  };
  auto remove_row = [table, model] {
    if (table->currentIndex().isValid()) model->removeRowAt(table->currentIndex().row());
  };
  connect(add, &QPushButton::clicked, this, insert_row);
  connect(remove, &QPushButton::clicked, this, remove_row);
  connect(import, &QPushButton::clicked, this, [this, path] { importListCsv(path); });
  connect(export_csv, &QPushButton::clicked, this, [this, path] { exportListCsv(path); });
  // The same four in the table's context menu.
  table->setContextMenuPolicy(Qt::ActionsContextMenu);
  table->addAction(tr("Insert row"), this, insert_row);
  table->addAction(tr("Remove row"), this, remove_row);
  auto* separator = new QAction(table);
  separator->setSeparator(true);
  table->addAction(separator);
  table->addAction(tr("Import CSV…"), this, [this, path] { importListCsv(path); });
  table->addAction(tr("Export CSV…"), this, [this, path] { exportListCsv(path); });
  connect(table->selectionModel(), &QItemSelectionModel::currentChanged, this,
          [this, model](const QModelIndex& current) {
            if (current.isValid() && !model->issue().isEmpty()) emit statusMessage(model->issue());
          });
  for (QPushButton* button : {add, remove, import, export_csv}) buttons->addWidget(button);
  buttons->addStretch(1);
  body->addLayout(buttons);
  // Core's message about the table, as a parameter row's Note column shows its own: below the
  // buttons, the block's whole width (a single list's buttons fill its own).
  block.issue = new QLabel(block.body);
  block.issue->setObjectName(key + "_issue");
  block.issue->setTextFormat(Qt::PlainText);
  block.issue->setWordWrap(true);
  block.issue->setStyleSheet("color: #aa0000;");
  block.issue->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  body->addWidget(block.issue);
  layout->addWidget(block.body, 1);
  lists_[list.key] = block;
  updateListBlock(block);
  return widget;
}

QWidget* CaseEditor::makeListRow(CaseGroup group, QWidget* parent) {
  QSplitter* row = nullptr;
  for (const CaseListTable& list : CaseListTables()) {
    if (list.group != group || lists_.count(list.key)) continue;
    if (!row) {
      row = new QSplitter(Qt::Horizontal, parent);
      row->setObjectName(QString("lists_%1").arg(int(group)));
      row->setChildrenCollapsible(false);
    }
    row->addWidget(makeListBlock(list, row));
    // A pair with its chart takes the room; a single list keeps to its table's width.
    row->setStretchFactor(row->count() - 1, list.columns.size() > 1 ? 1 : 0);
  }
  return row;
}

const CaseEditor::ListBlock* CaseEditor::listBlock(const std::string& path) const {
  const CaseListTable* list = FindCaseListTable(path);
  if (!list) return nullptr;
  const auto block = lists_.find(list->key);
  return block == lists_.end() ? nullptr : &block->second;
}

ArrayTableModel* CaseEditor::listModel(const std::string& path) const {
  const ListBlock* block = listBlock(path);
  return block ? block->model : nullptr;
}

QTableView* CaseEditor::listTable(const std::string& path) const {
  const ListBlock* block = listBlock(path);
  return block ? block->view : nullptr;
}

QChart* CaseEditor::listChart(const std::string& path) const {
  const ListBlock* block = listBlock(path);
  return block ? block->chart : nullptr;
}

QLabel* CaseEditor::listIssue(const std::string& path) const {
  const ListBlock* block = listBlock(path);
  return block ? block->issue : nullptr;
}

QLabel* CaseEditor::listHint(const std::string& path) const {
  const ListBlock* block = listBlock(path);
  return block ? block->hint : nullptr;
}

QLabel* CaseEditor::listAssumed(const std::string& path) const {
  const ListBlock* block = listBlock(path);
  return block ? block->assumed : nullptr;
}

bool CaseEditor::listEnabled(const std::string& path) const {
  const ListBlock* block = listBlock(path);
  return block && block->body->isEnabled();
}

QWidget* CaseEditor::makeProfilePage() {
  // Above: the skirt's inputs; below: the steady calculator on this case's skirt.
  auto* page = new QSplitter(Qt::Vertical, this);
  page->setObjectName("skirt_page");
  auto* splitter = new QSplitter(Qt::Horizontal, page);

  // Right: the axial profile above the ovality and the skirt's other lists (the liner's oil
  // film) side by side, each as table + chart (made first, so that none goes below the scalar
  // rows on the left).
  auto* right = new QSplitter(Qt::Vertical, splitter);
  right->setChildrenCollapsible(false);
  right->addWidget(makeListBlock(*FindCaseListTable("skirt.profile_y"), right));
  auto* lower = new QSplitter(Qt::Horizontal, right);
  lower->setChildrenCollapsible(false);
  lower->addWidget(makeListBlock(*FindCaseListTable("skirt.ovality_alpha"), lower));
  if (QWidget* others = makeListRow(CaseGroup::kSkirt, lower)) lower->addWidget(others);
  right->addWidget(lower);
  QWidget* parameters = makeParameterPage(CaseGroup::kSkirt);
  splitter->addWidget(parameters);
  splitter->addWidget(right);
  splitter->setStretchFactor(0, 2);
  splitter->setStretchFactor(1, 3);
  splitter->setSizes({600, 1000});
  // The pane is narrower than a page of its own: the quantity column at most 210 px (a longer
  // label elides; its tooltip has it whole), so that the notes ("assumed: …", "not used: …") keep
  // a readable width rather than sitting past a horizontal scroll bar.
  if (auto* table = parameters->findChild<QTableView*>(
          QString("parameters_%1").arg(int(CaseGroup::kSkirt)))) {
    QHeaderView* header = table->horizontalHeader();
    header->setSectionResizeMode(ParameterTableModel::kQuantity, QHeaderView::Interactive);
    table->resizeColumnToContents(ParameterTableModel::kQuantity);
    header->resizeSection(ParameterTableModel::kQuantity,
                          std::min(210, header->sectionSize(ParameterTableModel::kQuantity)));
    table->setTextElideMode(Qt::ElideRight);
  }
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
  const int table_width = FitWidthToHeaders(pressure_table_);
  pressure_chart_ =
      MakeChart(tr("crank angle [°CA] (360 = firing TDC)"), tr("cylinder pressure [MPa]"));
  pressure_chart_->legend()->show();
  auto* view = new QChartView(pressure_chart_, splitter);
  view->setRenderHint(QPainter::Antialiasing);
  splitter->addWidget(pressure_table_);
  splitter->addWidget(view);
  splitter->setStretchFactor(0, 0);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({table_width, 4 * table_width});
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
  for (const auto& [key, block] : lists_) updateListBlock(block);
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

void CaseEditor::updateListBlock(const ListBlock& block) {
  const engine::EngineCase& current = document_->engineCase();
  const QString issue = block.model->issue();
  block.issue->setText(issue);
  block.issue->setToolTip(issue);
  block.issue->setVisible(!issue.isEmpty());
  // Unused now: greyed with the reason, unless core refuses its rows (they must stay fixable).
  const QString unused = ListUnusedReason(*block.table, current);
  block.hint->setText(unused);
  block.hint->setVisible(!unused.isEmpty());
  block.body->setEnabled(unused.isEmpty() || !issue.isEmpty());
  // The columns' "assumed" notes (an edit of the table drops them: CaseDocument::edit).
  QStringList notes;
  for (const engine::CaseField* column : block.table->columns) {
    const auto note = current.assumed.find(column->path);
    if (note == current.assumed.end()) continue;
    const QString text = QString::fromStdString(note->second);
    if (!notes.contains(text)) notes << text;
  }
  const QString assumed = notes.isEmpty() ? QString() : tr("assumed: %1").arg(notes.join("; "));
  block.assumed->setText(assumed);
  block.assumed->setVisible(!assumed.isEmpty());
  if (!block.chart) return;
  // The pair in display units, the rows that are numbers.
  auto& c = const_cast<engine::EngineCase&>(document_->engineCase());  // accessors only locate
  const engine::CaseField& xf = *block.table->columns[0];
  const engine::CaseField& yf = *block.table->columns[1];
  const std::vector<double>& xs = xf.list(c);
  const std::vector<double>& ys = yf.list(c);
  QList<QPointF> points;
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
    const double x = xs[i] / xf.display_scale;
    const double y = ys[i] / yf.display_scale;
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    const bool first = points.isEmpty();
    points << QPointF(x, y);
    x0 = first ? x : std::min(x0, x);
    x1 = first ? x : std::max(x1, x);
    y0 = first ? y : std::min(y0, y);
    y1 = first ? y : std::max(y1, y);
  }
  static_cast<QLineSeries*>(block.chart->series().first())->replace(points);
  if (double a = 0, b = 0; ListChartXRange(*block.table, c, &a, &b)) {
    x0 = a;
    x1 = b;
  }
  FitAxes(block.chart, x0, x1, std::min(0.0, y0), y1);
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
  // A whole number or a decimal, not the tail of one ("1234.5rpm" is 1234.5, not 5).
  static const QRegularExpression rpm_re("(?<![\\d.])(\\d+(?:\\.\\d+)?)\\s*rpm",
                                         QRegularExpression::CaseInsensitiveOption);
  const auto match = rpm_re.match(QFileInfo(path).fileName());
  if (match.hasMatch()) rpm = match.captured(1).toDouble();
  curve.rpm = rpm;
  int index = -1;
  for (size_t i = 0; i < next.pressure_curves.size(); ++i) {
    if (next.pressure_curves[i].rpm == rpm) index = int(i);
  }
  const bool replaced = index >= 0;
  if (index < 0) {
    next.pressure_curves.push_back(curve);
    index = int(next.pressure_curves.size()) - 1;
  } else {
    next.pressure_curves[size_t(index)] = curve;
  }
  current_curve_ = index;
  document_->edit(next, tr("Import pressure curve %1").arg(QFileInfo(path).fileName()));
  curve_combo_->setCurrentIndex(index);
  emit statusMessage(tr("Imported %1 points at %2 rpm from %3%4")
                         .arg(curve.pressure.size())
                         .arg(rpm)
                         .arg(path, replaced ? tr(", replacing the curve at that speed (undo "
                                                  "brings it back)")
                                             : QString()));
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

namespace {

// "supply_pressure_curve.csv" for the "Supply pressure curve" table.
QString ListCsvFileName(const CaseListTable& list) {
  QString name = list.title.toLower();
  name.replace(QRegularExpression("[^a-z0-9]+"), "_");
  return name + ".csv";
}

}  // namespace

bool CaseEditor::importListCsv(const std::string& path, const QString& given_file) {
  const ListBlock* block = listBlock(path);
  if (!block) return false;
  QString file = given_file;
  if (file.isEmpty()) {
    file = QFileDialog::getOpenFileName(this, tr("Import %1").arg(block->table->title.toLower()),
                                        {}, tr("CSV files (*.csv *.txt);;All files (*)"));
    if (file.isEmpty()) return false;
  }
  std::vector<std::vector<double>> columns;
  QString error;
  if (!ReadListCsv(*block->table, file, &columns, &error)) {
    emit statusMessage(error);
    if (given_file.isEmpty()) QMessageBox::warning(this, tr("Import failed"), error);
    return false;
  }
  const size_t rows = columns.empty() ? 0 : columns.front().size();
  const bool changed = block->model->replaceColumns(
      columns, tr("Import %1 from %2").arg(block->model->editName(), QFileInfo(file).fileName()));
  emit statusMessage(
      changed
          ? (rows == 1 ? tr("Imported 1 row into the %1 from %2")
                       : tr("Imported %1 rows into the %2 from %3").arg(rows))
                .arg(block->model->editName(), file)
          : tr("%1 holds the rows of %2 already: nothing changed").arg(block->table->title, file));
  return true;
}

bool CaseEditor::exportListCsv(const std::string& path, const QString& given_file) {
  const ListBlock* block = listBlock(path);
  if (!block) return false;
  QString file = given_file;
  if (file.isEmpty()) {
    file = QFileDialog::getSaveFileName(this, tr("Export %1").arg(block->table->title.toLower()),
                                        ListCsvFileName(*block->table), tr("CSV files (*.csv)"));
    if (file.isEmpty()) return false;
  }
  QString error;
  if (!WriteListCsv(*block->table, document_->engineCase(), file, &error)) {
    emit statusMessage(error);
    if (given_file.isEmpty()) QMessageBox::warning(this, tr("Export failed"), error);
    return false;
  }
  emit statusMessage(tr("Wrote %1").arg(file));
  return true;
}

}  // namespace filmdyn::ui
