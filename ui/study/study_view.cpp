#include "ui/study/study_view.hpp"

#include <QAbstractTableModel>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QFileDialog>
#include <QFont>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QPushButton>
#include <QScatterSeries>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

#include "core/engine/case_schema.hpp"
#include "core/io/run_comparison.hpp"
#include "ui/charts/round_ticks.hpp"
#include "ui/plots/study_charts.hpp"

namespace filmdyn::ui {

namespace {

namespace fs = std::filesystem;

std::string ReasonAndNotes(const batch::StudyRow& r) {
  const std::string notes = io::NotesText(r.notes);
  if (r.reason.empty() || notes.empty()) return r.reason + notes;
  return r.reason + "; " + notes;
}

QString StateText(batch::PointState state) {
  return QString::fromStdString(batch::PointStateName(state));
}

// A point's state with its run's status where that says more: "done", "done (not converged)",
// "incomplete (time limit)"; not "done (completed)".
QString StateCellText(const batch::StudyRow& r) {
  QString text = StateText(r.state);
  const bool says_more = !r.status.empty() && r.status != batch::PointStateName(r.state) &&
                         !(r.state == batch::PointState::kDone && r.status == "completed");
  if (says_more) {
    QString status = QString::fromStdString(r.status);
    status.replace('-', ' ').replace('_', ' ');
    text += " (" + status + ")";
  }
  return text;
}

// Figures of a point that did not reach its run's end cover only the part it computed.
bool PartialFigures(const batch::StudyRow& r) {
  return r.state == batch::PointState::kFailed || r.state == batch::PointState::kIncomplete;
}

// The points as a table: point, the factors, state, wall time, the figures some point has,
// the reason of a point that failed or stopped and the notes of its figures. Qt::UserRole holds the
// value the column sorts by (a number, or a text; none for an empty cell).
class StudyTableModel : public QAbstractTableModel {
 public:
  StudyTableModel(const batch::Study* study, const std::vector<batch::StudyRow>* rows,
                  const std::vector<int>* figures, QObject* parent)
      : QAbstractTableModel(parent), study_(study), rows_(rows), figures_(figures) {}

  void reset() {
    beginResetModel();
    factors_.clear();
    for (const batch::StudyFactor& f : study_->factors) factors_.push_back(FactorDisplay(f));
    // Each figure's column in common decimals (about 4 significant digits for its largest value).
    decimals_.clear();
    for (int k : *figures_) {
      const double scale = io::ComparisonFigures()[size_t(k)].display_scale;
      std::vector<double> values;
      for (const batch::StudyRow& r : *rows_) {
        if (r.figures[size_t(k)]) values.push_back(*r.figures[size_t(k)] * scale);
      }
      decimals_.push_back(CommonDecimals(values));
    }
    endResetModel();
  }

  int rowCount(const QModelIndex& parent = {}) const override {
    return parent.isValid() ? 0 : int(rows_->size());
  }
  int columnCount(const QModelIndex& parent = {}) const override {
    return parent.isValid() ? 0 : 4 + int(factors_.size()) + int(figures_->size());
  }

  QVariant headerData(int section, Qt::Orientation orientation, int role) const override {
    if (orientation != Qt::Horizontal) return {};
    const int f = int(factors_.size());
    if (role == Qt::ToolTipRole) {
      // A factor's header is its case path, as the study file and study.csv name it: the tooltip
      // says what it is in the case editor's words; a figure's names its study.csv column.
      if (section >= 1 && section <= f) {
        const std::string& path = study_->factors[size_t(section - 1)].path;
        const engine::CaseField* field = engine::FindCaseField(path);
        return field ? QString::fromStdString(field->label + " (" + path + ")")
                     : QString::fromStdString(path);
      }
      if (section >= f + 3 && section < f + 3 + int(figures_->size()))
        return QString::fromStdString(
            io::ComparisonFigures()[size_t((*figures_)[size_t(section - f - 3)])].key);
      return {};
    }
    if (role != Qt::DisplayRole) return {};
    if (section == 0) return tr("point");
    if (section <= f) return factors_[size_t(section - 1)].title;
    if (section == f + 1) return tr("state");
    if (section == f + 2) return tr("wall time [s]");
    if (section < f + 3 + int(figures_->size())) {
      return QString::fromStdString(
          io::ComparisonFigures()[size_t((*figures_)[size_t(section - f - 3)])].display_name);
    }
    return tr("reason, notes");
  }

  QVariant data(const QModelIndex& index, int role) const override {
    if (!index.isValid()) return {};
    const batch::StudyRow& r = (*rows_)[size_t(index.row())];
    const int column = index.column();
    const int f = int(factors_.size());
    const int figure_end = f + 3 + int(figures_->size());
    auto number = [role](std::optional<double> v, double scale) -> QVariant {
      if (!v || !std::isfinite(*v)) return role == Qt::DisplayRole ? QVariant("–") : QVariant();
      if (role == Qt::DisplayRole) return QString::number(*v / scale, 'g', 5);
      return *v / scale;
    };
    const bool partial = PartialFigures(r) && column > f + 2 && column < figure_end &&
                         r.figures[size_t((*figures_)[size_t(column - f - 3)])].has_value();
    if (partial && (role == Qt::ForegroundRole || role == Qt::FontRole)) {
      if (role == Qt::ForegroundRole) return QColor(130, 130, 130);
      QFont font;
      font.setItalic(true);
      return font;
    }
    if (role == Qt::ToolTipRole) {
      const QString notes = QString::fromStdString(io::NotesText(r.notes));
      if (partial) {
        const std::string reason = ReasonAndNotes(r);
        return tr("Partial: the run %1 before the end of its cycles; this figure covers only "
                  "the part it computed")
                   .arg(r.state == batch::PointState::kFailed ? tr("failed") : tr("stopped")) +
               (reason.empty() ? QString() : "\n" + QString::fromStdString(reason));
      }
      if (column > f + 2 && column < figure_end && !notes.isEmpty()) {
        // A figure the run has but the comparison leaves out says why.
        const int k = (*figures_)[size_t(column - f - 3)];
        if (!r.figures[size_t(k)]) return notes;
      }
      const std::string text = ReasonAndNotes(r);
      if (text.empty()) return {};
      return QString::fromStdString(text);
    }
    if (role == Qt::ForegroundRole && column == f + 1) {
      switch (r.state) {
        case batch::PointState::kFailed:
          return QColor(180, 0, 0);
        case batch::PointState::kIncomplete:
          return QColor(170, 100, 0);
        case batch::PointState::kRunning:
          return QColor(0, 90, 170);
        default:
          return {};
      }
    }
    if (role == Qt::TextAlignmentRole) {
      return column == f + 1 || column == figure_end
                 ? QVariant(int(Qt::AlignLeft | Qt::AlignVCenter))
                 : QVariant(int(Qt::AlignRight | Qt::AlignVCenter));
    }
    if (role != Qt::DisplayRole && role != Qt::UserRole) return {};
    if (column == 0) return r.point.number;
    if (column <= f) {
      const std::size_t k = size_t(column - 1);
      if (r.point.numbers[k]) return number(r.point.numbers[k], factors_[k].scale);
      return FactorValueText(study_->factors[k], r.point.values[k], std::nullopt);
    }
    if (column == f + 1) return role == Qt::DisplayRole ? StateCellText(r) : StateText(r.state);
    if (column == f + 2) {
      if (role == Qt::DisplayRole && r.wall_time_s) return QString::number(*r.wall_time_s, 'f', 1);
      return number(r.wall_time_s, 1.0);
    }
    if (column < figure_end) {
      const std::size_t n = size_t(column - f - 3);
      const int k = (*figures_)[n];
      const io::ComparisonFigure& fig = io::ComparisonFigures()[size_t(k)];
      const std::optional<double>& value = r.figures[size_t(k)];
      if (role == Qt::DisplayRole && value && std::isfinite(*value) && n < decimals_.size() &&
          decimals_[n])
        return FixedDecimals(*value * fig.display_scale, *decimals_[n]);
      return number(value, 1.0 / fig.display_scale);
    }
    // The last column: why a point is not done (or its run's message), and the figures its run
    // has that the comparison leaves out.
    const std::string text = ReasonAndNotes(r);
    if (text.empty()) return role == Qt::DisplayRole ? QVariant("") : QVariant();
    return QString::fromStdString(text);
  }

 private:
  const batch::Study* study_;
  const std::vector<batch::StudyRow>* rows_;
  const std::vector<int>* figures_;
  std::vector<StudyFactorDisplay> factors_;
  std::vector<std::optional<int>> decimals_;  ///< per figure column (CommonDecimals)
};

// Sorts numbers as numbers and puts empty cells last in either order.
class StudySortProxy : public QSortFilterProxyModel {
 public:
  using QSortFilterProxyModel::QSortFilterProxyModel;

 protected:
  bool lessThan(const QModelIndex& left, const QModelIndex& right) const override {
    const QVariant a = left.data(Qt::UserRole), b = right.data(Qt::UserRole);
    if (a.isValid() != b.isValid()) {
      return sortOrder() == Qt::AscendingOrder ? a.isValid() : b.isValid();
    }
    if (!a.isValid()) return false;
    bool a_number = false, b_number = false;
    const double x = a.toDouble(&a_number), y = b.toDouble(&b_number);
    if (a_number && b_number && a.typeId() != QMetaType::QString &&
        b.typeId() != QMetaType::QString)
      return x < y;
    return QString::localeAwareCompare(a.toString(), b.toString()) < 0;
  }
};

}  // namespace

StudyView::StudyView(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* bar = new QHBoxLayout;
  auto* open = new QPushButton(tr("Open study folder…"), this);
  open->setObjectName("open_study");
  connect(open, &QPushButton::clicked, this, &StudyView::openInteractive);
  reload_button_ = new QPushButton(tr("Read again"), this);
  reload_button_->setObjectName("reload_study");
  reload_button_->setToolTip(
      tr("Read the points' folders again (done automatically every few "
         "seconds while points are pending or running)"));
  reload_button_->setEnabled(false);
  connect(reload_button_, &QPushButton::clicked, this, &StudyView::reload);
  open_run_button_ = new QPushButton(tr("Open run in results"), this);
  open_run_button_->setObjectName("open_point_run");
  open_run_button_->setToolTip(
      tr("Show the selected point's run beside the session's runs: its plots, figures and, when "
         "the study wrote them, film fields (or double-click a row)"));
  open_run_button_->setEnabled(false);
  connect(open_run_button_, &QPushButton::clicked, this, &StudyView::requestOpenRun);
  title_ = new QLabel(tr("No study open. Open the folder a <tt>filmdyn study</tt> wrote (it holds "
                         "study.json); docs/study.md tells how to make one."),
                      this);
  title_->setObjectName("study_title");
  title_->setTextFormat(Qt::RichText);
  title_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  title_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);  // never widens the window
  counts_ = new QLabel(this);
  counts_->setObjectName("study_counts");
  bar->addWidget(open);
  bar->addWidget(reload_button_);
  bar->addWidget(open_run_button_);
  bar->addSpacing(12);
  bar->addWidget(title_, 1);
  bar->addWidget(counts_);
  layout->addLayout(bar);

  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->setObjectName("study_splitter");
  model_ = new StudyTableModel(&study_, &rows_, &figures_, this);
  proxy_ = new StudySortProxy(this);
  proxy_->setSourceModel(model_);
  proxy_->setSortRole(Qt::UserRole);
  table_ = new QTableView(splitter);
  table_->setObjectName("study_table");
  table_->setModel(proxy_);
  table_->setSortingEnabled(true);
  table_->sortByColumn(0, Qt::AscendingOrder);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->setAlternatingRowColors(true);
  connect(table_, &QTableView::doubleClicked, this, &StudyView::requestOpenRun);
  connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, [this] {
    markSelection();
    open_run_button_->setEnabled(selectedPoint() > 0);
  });

  auto* plot = new QWidget(splitter);
  auto* plot_layout = new QVBoxLayout(plot);
  plot_layout->setContentsMargins(0, 0, 0, 0);
  auto* axes = new QHBoxLayout;
  figure_box_ = new QComboBox(plot);
  figure_box_->setObjectName("study_figure");
  factor_box_ = new QComboBox(plot);
  factor_box_->setObjectName("study_factor");
  axes->addWidget(figure_box_, 1);
  axes->addWidget(new QLabel(tr("against"), plot));
  axes->addWidget(factor_box_, 1);
  plot_layout->addLayout(axes);
  scatter_view_ = new QChartView(plot);
  scatter_view_->setObjectName("study_scatter");
  scatter_view_->setRenderHint(QPainter::Antialiasing);
  scatter_view_->setMinimumSize(240, 200);
  plot_layout->addWidget(scatter_view_, 1);
  splitter->addWidget(table_);
  splitter->addWidget(plot);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 2);
  layout->addWidget(splitter, 1);
  const auto rebuild = [this] { rebuildScatter(); };
  connect(figure_box_, &QComboBox::currentIndexChanged, this, rebuild);
  connect(factor_box_, &QComboBox::currentIndexChanged, this, rebuild);

  watcher_ = new QFutureWatcher<std::pair<std::vector<batch::StudyRow>, QString>>(this);
  connect(watcher_, &QFutureWatcherBase::finished, this, &StudyView::onLoaded);
  refresh_timer_ = new QTimer(this);
  refresh_timer_->setSingleShot(true);
  connect(refresh_timer_, &QTimer::timeout, this, [this] {
    if (isVisible()) {
      reload();
    } else {
      refresh_timer_->start();  // read again once the page is looked at
    }
  });
}

StudyView::~StudyView() {
  refresh_timer_->stop();
  watcher_->waitForFinished();  // the worker reads files only; it ends soon
  // The table model reads this view's members, which die before its child widgets: a shown
  // table hidden while they are deleted would still ask it for its headers.
  proxy_->setSourceModel(nullptr);
  delete model_;
  model_ = nullptr;
}

bool StudyView::openFolder(const QString& dir, QString* error) {
  batch::Study study;
  try {
    study = batch::ReadStudyFolder(fs::path(dir.toStdString()));
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  refresh_timer_->stop();
  ++opened_folder_;  // a read of the previous folder under way: its rows are dropped (onLoaded)
  folder_ = dir;
  study_ = std::move(study);
  rows_.clear();
  figures_.clear();
  static_cast<StudyTableModel*>(model_)->reset();
  title_->setText(tr("<b>%1</b> — %2, %3 — %4")
                      .arg(QString::fromStdString(study_.name).toHtmlEscaped(),
                           QString::fromStdString(batch::StudyDesignName(study_.design)),
                           study_.factors.size() == 1 ? tr("1 factor")
                                                      : tr("%1 factors").arg(study_.factors.size()),
                           dir.toHtmlEscaped()));
  factor_box_->blockSignals(true);
  factor_box_->clear();
  for (const batch::StudyFactor& f : study_.factors) factor_box_->addItem(FactorDisplay(f).title);
  factor_box_->blockSignals(false);
  reload_button_->setEnabled(true);
  reload();
  return true;
}

void StudyView::openInteractive() {
  QSettings settings;
  const QString dir = QFileDialog::getExistingDirectory(
      this, tr("Open study folder"), settings.value("paths/study_dir").toString());
  if (dir.isEmpty()) return;
  settings.setValue("paths/study_dir", QFileInfo(dir).absolutePath());
  QString error;
  if (!openFolder(dir, &error)) emit statusMessage(tr("Cannot open the study: %1").arg(error));
}

bool StudyView::isLoading() const { return watcher_->isRunning(); }

void StudyView::reload() {
  if (folder_.isEmpty() || watcher_->isRunning()) return;
  refresh_timer_->stop();
  counts_->setText(rows_.empty() ? tr("reading the points…") : counts_->text());
  const fs::path dir(folder_.toStdString());
  const batch::Study study = study_;
  read_folder_ = opened_folder_;
  watcher_->setFuture(QtConcurrent::run([dir, study] {
    std::pair<std::vector<batch::StudyRow>, QString> result;
    try {
      result.first = batch::CollectStudy(dir, study);
    } catch (const std::exception& e) {
      result.second = QString::fromUtf8(e.what());
    }
    return result;
  }));
}

void StudyView::onLoaded() {
  if (read_folder_ != opened_folder_) {  // the folder open before: read the one open now
    reload();
    return;
  }
  auto [rows, error] = watcher_->result();
  if (!error.isEmpty()) {
    counts_->setText(tr("cannot read the points"));
    emit statusMessage(tr("Cannot read the study's points: %1").arg(error));
    emit loaded();
    return;
  }
  const int selected = selectedPoint();
  rows_ = std::move(rows);
  figures_.clear();
  for (std::size_t k = 0; k < io::ComparisonFigures().size(); ++k) {
    if (std::any_of(rows_.begin(), rows_.end(),
                    [k](const batch::StudyRow& r) { return r.figures[k].has_value(); }))
      figures_.push_back(int(k));
  }
  static_cast<StudyTableModel*>(model_)->reset();
  fitLastColumn();
  // The figure box keeps its choice (by figure) across reads; by default the first figure.
  const int shown_figure =
      figure_box_->currentData().isValid() ? figure_box_->currentData().toInt() : -1;
  figure_box_->blockSignals(true);
  figure_box_->clear();
  for (int k : figures_) {
    figure_box_->addItem(QString::fromStdString(io::ComparisonFigures()[size_t(k)].display_name),
                         k);
  }
  figure_box_->setCurrentIndex(std::max(0, figure_box_->findData(shown_figure)));
  figure_box_->blockSignals(false);

  int counts[5] = {0, 0, 0, 0, 0};
  for (const batch::StudyRow& r : rows_) ++counts[int(r.state)];
  QStringList parts{rows_.size() == 1 ? tr("1 point") : tr("%1 points").arg(rows_.size())};
  for (batch::PointState s :
       {batch::PointState::kDone, batch::PointState::kFailed, batch::PointState::kIncomplete,
        batch::PointState::kRunning, batch::PointState::kPending}) {
    if (counts[int(s)] > 0) parts << QString("%1 %2").arg(counts[int(s)]).arg(StateText(s));
  }
  counts_->setText(parts.join(", "));
  rebuildScatter();
  if (selected > 0) selectPoint(selected);
  // A study still running is read again every few seconds.
  if (counts[int(batch::PointState::kPending)] + counts[int(batch::PointState::kRunning)] > 0) {
    refresh_timer_->start(5000);
  }
  emit loaded();
}

const batch::StudyRow* StudyView::row(int number) const {
  for (const batch::StudyRow& r : rows_) {
    if (r.point.number == number) return &r;
  }
  return nullptr;
}

void StudyView::selectPoint(int number) {
  for (int i = 0; i < proxy_->rowCount(); ++i) {
    if (proxy_->index(i, 0).data(Qt::UserRole).toInt() == number) {
      table_->selectRow(i);
      table_->scrollTo(proxy_->index(i, 0));
      return;
    }
  }
}

int StudyView::selectedPoint() const {
  const QModelIndexList selected = table_->selectionModel()->selectedRows();
  return selected.isEmpty() ? 0 : selected.first().data(Qt::UserRole).toInt();
}

bool StudyView::setScatter(int factor, int figure) {
  const int f = factor_box_->count() > factor ? factor : -1;
  const int k = figure_box_->findData(figure);
  if (f < 0 || k < 0) return false;
  factor_box_->setCurrentIndex(f);
  figure_box_->setCurrentIndex(k);
  rebuildScatter();
  return true;
}

void StudyView::rebuildScatter() {
  QChart* old = scatter_view_->chart();
  const int factor = factor_box_->currentIndex();
  const QVariant figure = figure_box_->currentData();
  QChart* chart = nullptr;
  if (factor >= 0 && figure.isValid()) {
    chart = MakeStudyScatterChart(study_, rows_, std::size_t(factor), std::size_t(figure.toInt()));
  } else {
    chart = new QChart;
    chart->setTitle(rows_.empty() ? tr("No points read yet") : tr("No point has figures yet"));
  }
  scatter_view_->setChart(chart);
  delete old;  // setChart releases the previous chart without deleting it
  if (auto* series = chart->series().isEmpty()
                         ? nullptr
                         : qobject_cast<QScatterSeries*>(chart->series().front())) {
    const std::vector<std::size_t> drawn = StudyScatterRows(rows_, std::size_t(figure.toInt()));
    connect(series, &QScatterSeries::clicked, this, [this, series, drawn](const QPointF& p) {
      const qsizetype k = series->points().indexOf(p);
      if (k >= 0 && size_t(k) < drawn.size()) selectPoint(rows_[drawn[size_t(k)]].point.number);
    });
  }
  markSelection();
}

void StudyView::fitLastColumn() {
  // The reasons and notes can be long sentences: their column is as wide as its text up to a
  // limit, the rest elided (the cell's tooltip has it whole); the other columns fit their text.
  QHeaderView* header = table_->horizontalHeader();
  const int last = proxy_->columnCount() - 1;
  if (last < 0) return;
  header->setSectionResizeMode(QHeaderView::ResizeToContents);
  header->setSectionResizeMode(last, QHeaderView::Interactive);
  table_->resizeColumnToContents(last);
  header->resizeSection(last, std::min(header->sectionSize(last), kLastColumnWidth));
}

void StudyView::markSelection() {
  QChart* chart = scatter_view_->chart();
  if (chart == nullptr || chart->series().isEmpty()) return;
  auto* series = qobject_cast<QScatterSeries*>(chart->series().front());
  if (series == nullptr) return;
  QScatterSeries* mark = nullptr;
  for (QAbstractSeries* s : chart->series()) {
    if (s->objectName() == "selected_point") mark = static_cast<QScatterSeries*>(s);
  }
  if (mark == nullptr) {
    mark = new QScatterSeries(chart);
    mark->setObjectName("selected_point");
    mark->setName(tr("selected"));
    mark->setMarkerSize(16);
    mark->setColor(Qt::transparent);
    mark->setBorderColor(QColor(200, 30, 30));
    mark->setPen(QPen(QColor(200, 30, 30), 2.5));
    chart->addSeries(mark);
    for (QAbstractAxis* axis : series->attachedAxes()) mark->attachAxis(axis);
    if (chart->legend() != nullptr) {
      for (QLegendMarker* m : chart->legend()->markers(mark)) m->setVisible(false);
    }
  }
  mark->clear();
  const int number = selectedPoint();
  const std::vector<std::size_t> drawn =
      StudyScatterRows(rows_, std::size_t(figure_box_->currentData().toInt()));
  for (std::size_t k = 0; k < drawn.size() && k < size_t(series->count()); ++k) {
    if (rows_[drawn[k]].point.number == number) mark->append(series->at(qsizetype(k)));
  }
}

void StudyView::requestOpenRun() {
  const int number = selectedPoint();
  const batch::StudyRow* r = row(number);
  if (r == nullptr) return;
  if (r->state == batch::PointState::kPending || r->state == batch::PointState::kRunning) {
    emit statusMessage(
        tr("Point %1 is %2: it has no results to show yet").arg(number).arg(StateText(r->state)));
    return;
  }
  emit openRunRequested(number);
}

}  // namespace filmdyn::ui
