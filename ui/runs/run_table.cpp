#include "ui/runs/run_table.hpp"

#include <QHeaderView>
#include <cmath>

#include "ui/runs/run_figures.hpp"

namespace filmdyn::ui {

namespace {

QString Number(double v, double scale, int decimals = 2) {
  return std::isfinite(v) ? QString::number(v * scale, 'f', decimals) : QStringLiteral("–");
}

// "≤ 0.4 %", "2.8 %" in red with a warning sign above the threshold, "–" when not estimated;
// the tooltip lists every headline figure with its estimate.
void ShowErrorEstimate(const engine::ErrorEstimate& e, QTableWidgetItem* cell) {
  QString text = QStringLiteral("–");
  if (e.Estimated()) {
    const QString percent = QString::number(100.0 * e.worst_relative, 'g', 2);
    text = e.Warn() ? QString("⚠ %1 %").arg(percent) : QString("≤ %1 %").arg(percent);
  } else if (e.status == "unavailable") {
    text = QStringLiteral("⚠ not estimated");
  }
  QString tip = QString::fromStdString(e.Summary());
  for (const engine::FigureError& f : e.figures) {
    // Unit from the key ("bearing_moft_min[m]"): lengths in µm, pressures in MPa.
    const QString key = QString::fromStdString(f.figure.key);
    double scale = 1.0;
    QString unit = key.section('[', 1).section(']', 0, 0);
    if (unit == "m") scale = 1e6, unit = "µm";
    if (unit == "Pa") scale = 1e-6, unit = "MPa";
    if (unit == "-") unit.clear();
    tip += QString("\n%1: %2 %3, %4%5 % → %6 %3")
               .arg(QString::fromStdString(f.figure.label))
               .arg(QString::number(f.figure.value * scale, 'g', 5))
               .arg(unit)
               .arg(f.error >= 0 ? "+" : "−")
               .arg(QString::number(100.0 * f.relative, 'g', 2))
               .arg(QString::number((f.figure.value + f.error) * scale, 'g', 5));
  }
  if (e.Estimated()) {
    tip += QString("\n(value, estimated error, extrapolated value = value + error; from a "
                   "companion run on meshes with half the elements, %1 s)")
               .arg(QString::number(e.coarse_wall_time, 'f', 1));
  }
  cell->setText(text);
  cell->setToolTip(tip);
  cell->setForeground(e.Warn() ? QBrush(QColor(180, 0, 0)) : QBrush());
}

}  // namespace

RunTable::RunTable(QWidget* parent) : QTableWidget(0, kColumns, parent) {
  setObjectName("run_table");
  setHorizontalHeaderLabels({tr("Show"), tr("Run"), tr("Status"), tr("Cycles"), tr("Wall [s]"),
                             tr("max |e₀| [µm]"), tr("max |γ| [mrad]"), tr("min MOFT skirt [µm]"),
                             tr("min MOFT big end [µm]"), tr("mean FPL skirt [W]"),
                             tr("mean FPL big end [W]"), tr("max |F big end| [kN]"), tr("Discretisation error"),
                             tr("Reason")});
  setSelectionBehavior(QAbstractItemView::SelectRows);
  setSelectionMode(QAbstractItemView::SingleSelection);
  setEditTriggers(QAbstractItemView::NoEditTriggers);
  horizontalHeader()->setStretchLastSection(true);
  horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  horizontalHeader()->setSectionResizeMode(kReason, QHeaderView::Stretch);
  verticalHeader()->hide();
  verticalHeader()->setDefaultSectionSize(22);
  connect(this, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    if (updating_ || item->column() != kShow) return;
    emit visibilityToggled(item->data(Qt::UserRole).toInt(), item->checkState() == Qt::Checked);
  });
}

int RunTable::rowOf(int run_id) const {
  for (size_t i = 0; i < runs_.size(); ++i) {
    if (runs_[i]->id() == run_id) return int(i);
  }
  return -1;
}

void RunTable::updateRun(const RunHandle& run) {
  updating_ = true;
  int row = rowOf(run->id());
  if (row < 0) {
    runs_.push_back(run);
    row = rowCount();
    insertRow(row);
    auto* show = new QTableWidgetItem;
    show->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    show->setCheckState(Qt::Checked);
    show->setData(Qt::UserRole, run->id());
    setItem(row, kShow, show);
    for (int c = kRun; c < kColumns; ++c) setItem(row, c, new QTableWidgetItem);
  }
  const RunFigures f = ComputeRunFigures(run->samples());
  const auto stats = run->statistics();
  const RunProgress progress = run->progress();
  item(row, kRun)->setText(QString("#%1 %2").arg(run->id()).arg(run->label()));
  item(row, kStatus)->setText(RunStatusText(run->status()));
  item(row, kCycles)
      ->setText(QString::number(stats.count("cycles") ? int(stats.at("cycles")) : progress.cycle));
  item(row, kWall)->setText(QString::number(run->elapsedSeconds(), 'f', 2));
  item(row, kLateral)->setText(Number(f.max_abs_lateral, 1e6));
  item(row, kTilt)->setText(Number(f.max_abs_tilt, 1e3, 3));
  item(row, kSkirtMoft)->setText(Number(f.min_skirt_moft, 1e6));
  item(row, kBearingMoft)->setText(Number(f.min_bearing_moft, 1e6));
  item(row, kSkirtFpl)->setText(Number(f.mean_skirt_fpl, 1.0, 1));
  item(row, kBearingFpl)->setText(Number(f.mean_bearing_fpl, 1.0, 1));
  item(row, kBigEndForce)->setText(Number(f.max_big_end_force, 1e-3));
  ShowErrorEstimate(run->errorEstimate(), item(row, kError));
  item(row, kReason)->setText(run->reason());
  item(row, kReason)->setToolTip(run->reason());
  const bool failed = run->status() == RunStatus::kFailed;
  item(row, kStatus)->setForeground(failed ? QBrush(QColor(180, 0, 0)) : QBrush());
  updating_ = false;
  resizeColumnToContents(kRun);
}

void RunTable::removeRun(int run_id) {
  const int row = rowOf(run_id);
  if (row < 0) return;
  runs_.erase(runs_.begin() + row);
  removeRow(row);
}

RunHandle RunTable::currentRun() const {
  const int row = currentRow();
  if (row >= 0 && row < int(runs_.size())) return runs_[size_t(row)];
  return runs_.empty() ? nullptr : runs_.back();
}

}  // namespace filmdyn::ui
