#include "ui/runs/run_table.hpp"

#include <QAction>
#include <QContextMenuEvent>
#include <QHeaderView>
#include <QInputDialog>
#include <QMenu>
#include <QSet>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/base/angles.hpp"
#include "core/engine/case_diff.hpp"
#include "core/engine/error_estimate.hpp"
#include "core/io/run_kpis.hpp"
#include "ui/runs/run_figures.hpp"

namespace filmdyn::ui {

namespace {

QString Number(double v, double scale, int decimals = 2) {
  return std::isfinite(v) ? QString::number(v * scale, 'f', decimals) : QStringLiteral("–");
}

// Why a largest big-end force is marked: a spike between the output samples.
QString BigEndForceSpikeTip(const RunFigures& f) {
  QStringList beside;
  for (double v : {f.big_end_force_before, f.big_end_force_after})
    if (std::isfinite(v)) beside << QString::number(v * 1e-3, 'g', 3);
  return QString(
             "max big-end force %1 kN is a spike the output samples do not resolve (the "
             "samples beside it show %2 kN): an impact lasting a fraction of the output "
             "interval, whose sampled height depends on the output interval; a smaller "
             "solver.output_interval resolves it")
      .arg(QString::number(f.max_big_end_force * 1e-3, 'g', 4), beside.join(" and "));
}

// "≤ 0.4 %", "2.8 %" in red with a warning sign above the threshold, "–" when not estimated;
// the tooltip lists every headline figure with its estimate, then how far the figures moved over
// the last cycles (the time integration's scatter, which the mesh estimate does not hold).
void ShowErrorEstimate(const engine::ErrorEstimate& e,
                       const std::optional<engine::CycleScatter>& scatter, QTableWidgetItem* cell) {
  QString text = QStringLiteral("–");
  if (e.Estimated()) {
    const QString percent = QString::number(100.0 * e.worst_relative, 'g', 2);
    text = e.Warn() ? QString("⚠ %1 %").arg(percent) : QString("≤ %1 %").arg(percent);
  } else if (e.status == "unavailable") {
    text = QStringLiteral("⚠ not estimated");
  }
  // Rich text, so that Qt wraps the summary line (a run with a mass-conserving film adds a
  // long note to it); one line per figure below it.
  QStringList lines;
  for (const engine::FigureError& f : e.figures) {
    const engine::DisplayUnit display = engine::HeadlineDisplayUnit(f.figure.key);
    const double scale = display.scale;
    // "1.3639 µm"; a dimensionless figure without a unit ("0.97272").
    const QString unit =
        display.unit.empty() ? QString() : " " + QString::fromStdString(display.unit);
    if (!f.resolved_in_time) {
      lines << QString("%1: %2%3, %4")
                   .arg(QString::fromStdString(f.figure.label))
                   .arg(QString::number(f.figure.value * scale, 'g', 5))
                   .arg(unit)
                   .arg(QString::fromUtf8(engine::kUnresolvedPeakNote))
                   .toHtmlEscaped();
      continue;
    }
    // An extreme the meshes put at different places in the cycle: both crank angles.
    const QString where =
        f.extreme_elsewhere && f.crank_angle && f.extrapolated_crank_angle
            ? QString(" (at %1 °CA, extrapolated at %2 °CA)")
                  .arg(engine::CycleCrankAngleDeg(*f.crank_angle), 0, 'f', 0)
                  .arg(engine::CycleCrankAngleDeg(*f.extrapolated_crank_angle), 0, 'f', 0)
            : QString();
    // A companion far from the run: the estimate is rough (the summary line says why).
    const QString rough = f.far_companion
                              ? QString(" — rough: the coarser mesh's value lies %1 % away")
                                    .arg(100.0 * f.CompanionDistance(), 0, 'f', 0)
                              : QString();
    lines << QString("%1: %2%3, %4%5 % → %6%3%7%8")
                 .arg(QString::fromStdString(f.figure.label))
                 .arg(QString::number(f.figure.value * scale, 'g', 5))
                 .arg(unit)
                 .arg(f.error >= 0 ? "+" : "−")
                 .arg(QString::number(100.0 * f.relative, 'g', 2))
                 .arg(QString::number((f.figure.value + f.error) * scale, 'g', 5))
                 .arg(where)
                 .arg(rough)
                 .toHtmlEscaped();
  }
  QString tip = "<p>" + QString::fromStdString(e.Summary()).toHtmlEscaped() + "</p>";
  if (!lines.isEmpty()) tip += "<p>" + lines.join("<br>") + "</p>";
  if (e.Estimated()) {
    tip += QString(
               "<p>(value, estimated error, extrapolated value = value + error; from a "
               "companion run on meshes with half the elements, %1 s)</p>")
               .arg(QString::number(e.coarse_wall_time, 'f', 1));
  }
  if (scatter) {
    tip += "<p>" +
           (QString::fromStdString(scatter->Summary()) +
            QStringLiteral(" (a lower bound on the time integration's scatter; "
                           "docs/validation/errors.md)"))
               .toHtmlEscaped() +
           "</p>";
  }
  cell->setText(text);
  cell->setToolTip(tip);
  cell->setForeground(e.Warn() ? QBrush(QColor(180, 0, 0)) : QBrush());
}

// The run's engineering warnings: the first film or eccentricity warning (else the first one)
// as "⚠ h/σ 0.72 < 1 big end", "+2" for the others, red when the film or the steady state is
// at stake; the tooltip holds every message.
void ShowEngineeringWarnings(const std::vector<io::RunWarning>& warnings, QTableWidgetItem* cell) {
  if (warnings.empty()) {
    cell->setText(QStringLiteral("–"));
    cell->setToolTip(QString());
    cell->setForeground(QBrush());
    return;
  }
  auto serious = [](const io::RunWarning& w) {
    return w.code == "asperity_contact" || w.code == "mixed_lubrication" ||
           w.code == "high_eccentricity" || w.code == "not_periodic";
  };
  const auto first = std::find_if(warnings.begin(), warnings.end(), serious);
  const io::RunWarning& shown = first != warnings.end() ? *first : warnings.front();
  QString text = "⚠ " + QString::fromStdString(io::WarningShortText(shown));
  if (warnings.size() > 1) text += QString(" +%1").arg(warnings.size() - 1);
  QString tip;  // rich text, so that Qt wraps the long messages
  for (const io::RunWarning& w : warnings) {
    tip += "<p>⚠ " + QString::fromStdString(w.message).toHtmlEscaped() + "</p>";
  }
  cell->setText(text);
  cell->setToolTip(tip);
  cell->setForeground(first != warnings.end() ? QBrush(QColor(180, 0, 0)) : QBrush());
}

}  // namespace

RunTable::RunTable(QWidget* parent) : QTableWidget(0, kColumns, parent) {
  setObjectName("run_table");
  setHorizontalHeaderLabels({tr("Show"),
                             tr("Run"),
                             tr("Differences from the base run"),
                             tr("Status"),
                             tr("Warnings"),
                             tr("Cycles"),
                             tr("Wall [s]"),
                             tr("max |e₀| [µm]"),
                             tr("max |γ| [mrad]"),
                             tr("min MOFT skirt [µm]"),
                             tr("min MOFT big end [µm]"),
                             tr("mean FPL skirt [W]"),
                             tr("mean FPL big end [W]"),
                             tr("FMEP skirt [kPa]"),
                             tr("FMEP big end [kPa]"),
                             tr("oil skirt [mm³/cycle]"),
                             tr("oil big end [mm³/cycle]"),
                             tr("max |F big end| [kN]"),
                             tr("Discretisation error"),
                             tr("Notes"),
                             tr("Reason")});
  setSelectionBehavior(QAbstractItemView::SelectRows);
  setSelectionMode(QAbstractItemView::SingleSelection);
  // Only the name cell is edited in place (its flags); notes open a multi-line editor.
  setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
  horizontalHeader()->setStretchLastSection(true);
  horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  horizontalHeader()->setSectionResizeMode(kReason, QHeaderView::Stretch);
  horizontalHeader()->setSectionResizeMode(kRun, QHeaderView::Interactive);
  horizontalHeader()->setSectionResizeMode(kDifferences, QHeaderView::Interactive);
  verticalHeader()->hide();
  verticalHeader()->setDefaultSectionSize(22);
  connect(this, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    if (updating_) return;
    const int row = item->row();
    if (row < 0 || row >= int(runs_.size())) return;
    const int id = runs_[size_t(row)]->id();
    if (item->column() == kShow) {
      emit visibilityToggled(id, item->checkState() == Qt::Checked);
    } else if (item->column() == kRun) {
      QString error;
      if (!renameRun(id, item->text(), &error)) {
        emit statusMessage(error);
        fillIdentity(row);  // back to the run's label
      }
    }
  });
  // Alt+↑ / Alt+↓ move the selected run (the context menu offers the same).
  for (const auto& [key, delta] : {std::pair{Qt::Key_Up, -1}, std::pair{Qt::Key_Down, +1}}) {
    auto* move = new QAction(this);
    move->setShortcut(QKeySequence(Qt::ALT | key));
    move->setShortcutContext(Qt::WidgetShortcut);
    const int step = delta;  // (a structured binding cannot be captured before C++20's P1091)
    connect(move, &QAction::triggered, this, [this, step] {
      if (const RunHandle run = currentRun()) moveRun(run->id(), step);
    });
    addAction(move);
  }
  connect(this, &QTableWidget::cellDoubleClicked, this, [this](int row, int column) {
    if (column != kNotes || row < 0 || row >= int(runs_.size())) return;
    const RunHandle run = runs_[size_t(row)];
    bool ok = false;
    const QString notes = QInputDialog::getMultiLineText(
        this, tr("Notes"), tr("Notes on %1:").arg(run->label()), run->notes(), &ok);
    if (ok) setRunNotes(run->id(), notes);
  });
}

// The cells that say which run a row is: name, differences, notes, and the status of a run
// that could not be read back.
void RunTable::fillIdentity(int row) {
  const RunHandle& run = runs_[size_t(row)];
  const bool was_updating = updating_;
  updating_ = true;
  QTableWidgetItem* name = item(row, kRun);
  name->setText(run->label());
  name->setToolTip(
      tr("Run %1 · %2\nautomatic label: %3\nDouble-click to rename; an empty name "
         "restores the automatic label.")
          .arg(run->id())
          .arg(RunLabel(QString::fromStdString(run->request().model), run->request().rpm))
          .arg(run->automaticLabel()));
  QFont font = name->font();
  font.setBold(run->id() == baseRunId());
  name->setFont(font);
  const QString differences = run->id() == baseRunId()       ? tr("base run")
                              : run->differences().isEmpty() ? tr("same inputs")
                                                             : run->differences();
  item(row, kDifferences)->setText(differences);
  item(row, kDifferences)
      ->setToolTip(difference_tips_.value(run->id()).isEmpty()
                       ? differences
                       : tr("Differences from the base run %1:\n%2")
                             .arg(runs_[size_t(rowOf(baseRunId()))]->label(),
                                  difference_tips_.value(run->id())));
  // Notes: the first line in the cell, marked "…" when there is more; all of it in the tooltip.
  const QString notes = run->notes();
  const QString first = notes.section('\n', 0, 0);
  item(row, kNotes)->setText(first.size() < notes.trimmed().size() ? first + " …" : first);
  item(row, kNotes)
      ->setToolTip(notes.isEmpty() ? tr("Double-click to write notes on this run") : notes);
  if (!run->restoreError().isEmpty()) {
    item(row, kStatus)->setText(tr("not restored"));
    item(row, kStatus)->setForeground(QBrush(QColor(180, 0, 0)));
    item(row, kStatus)->setToolTip(run->restoreError());
  }
  updating_ = was_updating;
}

int RunTable::baseRunId() const {
  if (rowOf(base_id_) >= 0) return base_id_;
  return runs_.empty() ? -1 : runs_.front()->id();
}

void RunTable::setBaseRun(int run_id) {
  if (rowOf(run_id) < 0) return;
  base_id_ = run_id;
  relabel();
}

bool RunTable::renameRun(int run_id, const QString& name, QString* error) {
  const int row = rowOf(run_id);
  if (row < 0) return false;
  const RunHandle& run = runs_[size_t(row)];
  QString wanted = name.trimmed();
  if (wanted == run->automaticLabel()) wanted.clear();  // the automatic label: no own name
  for (const RunHandle& other : runs_) {
    if (other != run && !wanted.isEmpty() && other->label() == wanted) {
      if (error) {
        *error = tr("Run not renamed: another run is already called “%1”; each run needs its own "
                    "name")
                     .arg(wanted);
      }
      return false;
    }
  }
  run->setName(wanted);
  relabel();
  return true;
}

void RunTable::setRunNotes(int run_id, const QString& notes) {
  const int row = rowOf(run_id);
  if (row < 0) return;
  runs_[size_t(row)]->setNotes(notes);
  fillIdentity(row);
  emit runsEdited();
}

void RunTable::moveRun(int run_id, int delta) {
  const int from = rowOf(run_id);
  const int to = from + delta;
  if (from < 0 || to < 0 || to >= int(runs_.size()) || delta == 0) return;
  updating_ = true;
  const int current_column = std::max(0, currentColumn());
  std::vector<QTableWidgetItem*> taken;
  for (int c = 0; c < kColumns; ++c) taken.push_back(takeItem(from, c));
  removeRow(from);
  insertRow(to);
  for (int c = 0; c < kColumns; ++c) setItem(to, c, taken[size_t(c)]);
  const RunHandle run = runs_[size_t(from)];
  runs_.erase(runs_.begin() + from);
  runs_.insert(runs_.begin() + to, run);
  updating_ = false;
  setCurrentCell(to, current_column);
  relabel();  // the first run may be the base
  emit orderChanged(orderIds());
}

void RunTable::setRunVisible(int run_id, bool visible) {
  const int row = rowOf(run_id);
  if (row >= 0) item(row, kShow)->setCheckState(visible ? Qt::Checked : Qt::Unchecked);
}

bool RunTable::isRunVisible(int run_id) const {
  const int row = rowOf(run_id);
  return row >= 0 && item(row, kShow)->checkState() == Qt::Checked;
}

void RunTable::removeFinishedRuns() {
  for (int row = int(runs_.size()) - 1; row >= 0; --row) {
    if (runs_[size_t(row)]->status() != RunStatus::kRunning) {
      runs_.erase(runs_.begin() + row);
      removeRow(row);
    }
  }
  base_id_ = -1;
  relabel();
}

QList<int> RunTable::orderIds() const {
  QList<int> ids;
  for (const RunHandle& run : runs_) ids << run->id();
  return ids;
}

void RunTable::relabel() {
  QList<int> changed;
  const int base_id = baseRunId();
  const int base_row = rowOf(base_id);
  engine::RunInputs base;
  if (base_row >= 0) {
    const RunRequest& r = runs_[size_t(base_row)]->request();
    base = {r.engine_case, r.model, r.rpm};
  }
  // Names the user gave come first; an automatic label that repeats one gets the run's number.
  QSet<QString> used;
  for (const RunHandle& run : runs_) {
    if (!run->name().isEmpty()) used.insert(run->name());
  }
  for (const RunHandle& run : runs_) {
    const RunRequest& r = run->request();
    const QString model_speed = RunLabel(QString::fromStdString(r.model), r.rpm);
    QString automatic = model_speed;
    if (run->id() == base_id) {
      run->setDifferences({});
    } else {
      std::vector<engine::CaseDifference> d =
          engine::DiffRunInputs(base, {r.engine_case, r.model, r.rpm});
      // The physics first; numerical settings (solver, meshes) after it.
      std::stable_partition(d.begin(), d.end(), [](const engine::CaseDifference& x) {
        return x.path.rfind("solver.", 0) != 0 && x.path.find(".mesh_") == std::string::npos;
      });
      run->setDifferences(QString::fromStdString(engine::FormatDifferences(d)));
      QString tip;
      for (const engine::CaseDifference& x : d) {
        tip += QString("%1%2: %3 → %4")
                   .arg(tip.isEmpty() ? "" : "\n")
                   .arg(QString::fromStdString(x.label.empty() ? x.path : x.label))
                   .arg(QString::fromStdString(x.value_a), QString::fromStdString(x.value_b));
      }
      difference_tips_[run->id()] = tip;
      // A label stays short: the first differences and how many more the table lists.
      constexpr size_t kLabelDifferences = 3;
      if (!d.empty()) {
        const size_t shown = std::min(d.size(), kLabelDifferences);
        automatic =
            QString::fromStdString(engine::FormatDifferences({d.begin(), d.begin() + long(shown)}));
        if (d.size() > shown) automatic += tr(" · +%1 more").arg(d.size() - shown);
      }
    }
    if (used.contains(automatic)) automatic = tr("%1 (run %2)").arg(automatic).arg(run->id());
    used.insert(automatic);
    run->setAutomaticLabel(automatic);
  }
  for (size_t i = 0; i < runs_.size(); ++i) {
    fillIdentity(int(i));
    const QString label = runs_[i]->label();
    if (shown_labels_.value(runs_[i]->id()) != label) changed << runs_[i]->id();
    shown_labels_[runs_[i]->id()] = label;
  }
  // Long names and lists of differences are cut with "…" (the tooltip has them whole).
  for (int column : {int(kRun), int(kDifferences)}) {
    resizeColumnToContents(column);
    setColumnWidth(column, std::min(columnWidth(column), column == kRun ? 280 : 360));
  }
  if (!changed.isEmpty()) emit labelsChanged(changed);
}

void RunTable::contextMenuEvent(QContextMenuEvent* event) {
  const int row = rowAt(event->pos().y());
  if (row < 0 || row >= int(runs_.size())) return;
  selectRow(row);
  const RunHandle run = runs_[size_t(row)];
  const int id = run->id();
  QMenu menu(this);
  QAction* base = menu.addAction(tr("Use as &base run"), this, [this, id] { setBaseRun(id); });
  base->setCheckable(true);
  base->setChecked(id == baseRunId());
  menu.addAction(tr("&Rename…"), this, [this, row] { editItem(item(row, kRun)); });
  menu.addAction(tr("Edit &notes…"), this, [this, row] { emit cellDoubleClicked(row, kNotes); });
  menu.addSeparator();
  QAction* up = menu.addAction(tr("Move &up"), this, [this, id] { moveRun(id, -1); });
  up->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Up));
  up->setEnabled(row > 0);
  QAction* down = menu.addAction(tr("Move &down"), this, [this, id] { moveRun(id, +1); });
  down->setShortcut(QKeySequence(Qt::ALT | Qt::Key_Down));
  down->setEnabled(row + 1 < int(runs_.size()));
  menu.addSeparator();
  menu.addAction(tr("Re&move"), this, [this, id] { emit removeRequested(id); })
      ->setEnabled(run->status() != RunStatus::kRunning);
  menu.exec(event->globalPos());
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
    for (int c = kRun; c < kColumns; ++c) {
      auto* cell = new QTableWidgetItem;
      if (c != kRun) cell->setFlags(cell->flags() & ~Qt::ItemIsEditable);
      setItem(row, c, cell);
    }
    relabel();  // the new run's differences from the base run
  }
  const std::vector<RunSample> samples = run->samples();
  RunFigures f = ComputeRunFigures(samples, engine::ParseModel(run->request().model));
  // A run that ended before its first cycle did (stopped in its run-in) has no cycle means, as
  // its summary.json has none: the part computed is not a cycle. A running run shows the cycle
  // in progress.
  const bool whole_cycle =
      samples.size() >= 2 &&
      engine::SpanIsACycle(samples.size(), std::fmod(samples[1][Column::kCrankAngle] -
                                                         samples[0][Column::kCrankAngle] + 720.0,
                                                     720.0) *
                                               kRadiansPerDegree);
  if (run->status() != RunStatus::kRunning && !whole_cycle)
    f.mean_skirt_fpl = f.mean_bearing_fpl = std::numeric_limits<double>::quiet_NaN();
  const auto stats = run->statistics();
  const RunProgress progress = run->progress();
  item(row, kStatus)->setText(RunStatusText(run->status()));
  // A run whose folder could not be read back has no cycle count or wall time to show (not 0).
  const bool unknown = !run->restoreError().isEmpty();
  item(row, kCycles)
      ->setText(unknown ? QString("–")
                        : QString::number(stats.count("cycles") ? int(stats.at("cycles"))
                                                                : progress.cycle));
  item(row, kWall)
      ->setText(unknown ? QString("–") : QString::number(run->elapsedSeconds(), 'f', 2));
  item(row, kLateral)->setText(Number(f.max_abs_lateral, 1e6));
  item(row, kTilt)->setText(Number(f.max_abs_tilt, 1e3, 3));
  item(row, kSkirtMoft)->setText(Number(f.min_skirt_moft, 1e6));
  item(row, kBearingMoft)->setText(Number(f.min_bearing_moft, 1e6));
  item(row, kSkirtFpl)->setText(Number(f.mean_skirt_fpl, 1.0, 1));
  item(row, kBearingFpl)->setText(Number(f.mean_bearing_fpl, 1.0, 1));
  // Friction mean effective pressure: the mean friction power's work per cycle and swept volume.
  const RunRequest& request = run->request();
  auto fmep = [&](double fpl) {
    return std::isfinite(fpl) ? io::FrictionMep(fpl, request.engine_case.geometry, request.rpm)
                              : fpl;
  };
  item(row, kSkirtFmep)->setText(Number(fmep(f.mean_skirt_fpl), 1e-3, 2));
  item(row, kBearingFmep)->setText(Number(fmep(f.mean_bearing_fpl), 1e-3, 2));
  // Oil per cycle: mass-conserving films only, once the run has reported a whole cycle.
  auto oil = [&stats](const char* name) {
    const auto it = stats.find(name);
    return it == stats.end() ? std::nan("") : it->second;
  };
  item(row, kSkirtOil)->setText(Number(oil(kSkirtOilStatistic), 1e9, 1));
  item(row, kBearingOil)->setText(Number(oil(kBigEndOilStatistic), 1e9, 1));
  // A largest force that is an impact between the output samples is marked, and says so.
  item(row, kBigEndForce)
      ->setText((f.big_end_force_spike ? QStringLiteral("⚠ ") : QString()) +
                Number(f.max_big_end_force, 1e-3));
  item(row, kBigEndForce)->setToolTip(f.big_end_force_spike ? BigEndForceSpikeTip(f) : QString());
  ShowEngineeringWarnings(run->engineeringWarnings(), item(row, kWarnings));
  ShowErrorEstimate(run->errorEstimate(), run->cycleScatter(), item(row, kError));
  item(row, kReason)->setText(run->reason());
  item(row, kReason)->setToolTip(run->reason());
  const bool failed = run->status() == RunStatus::kFailed;
  item(row, kStatus)->setForeground(failed ? QBrush(QColor(180, 0, 0)) : QBrush());
  fillIdentity(row);
  updating_ = false;
  resizeColumnToContents(kRun);
  setColumnWidth(kRun, std::min(columnWidth(kRun), 280));
}

void RunTable::removeRun(int run_id) {
  const int row = rowOf(run_id);
  if (row < 0) return;
  runs_.erase(runs_.begin() + row);
  removeRow(row);
  relabel();  // the base run may have gone
}

RunHandle RunTable::currentRun() const {
  const int row = currentRow();
  if (row >= 0 && row < int(runs_.size())) return runs_[size_t(row)];
  return runs_.empty() ? nullptr : runs_.back();
}

}  // namespace filmdyn::ui
