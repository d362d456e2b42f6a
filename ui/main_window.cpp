#include "ui/main_window.hpp"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QProgressBar>
#include <QScrollBar>
#include <QSettings>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "core/engine/error_estimate.hpp"
#include "core/io/case_file.hpp"
#include "core/io/output_files.hpp"
#include "core/io/results_writer.hpp"
#include "ui/about_info.hpp"
#include "ui/autosave.hpp"
#include "ui/case_editor/case_document.hpp"
#include "ui/case_editor/case_editor.hpp"
#include "ui/case_editor/case_json.hpp"
#include "ui/case_editor/case_parameters.hpp"
#include "ui/charts/chart_export.hpp"
#include "ui/fields/field_view.hpp"
#include "ui/help/help_browser.hpp"
#include "ui/plots/plot_panel.hpp"
#include "ui/run/run_controller.hpp"
#include "ui/runs/run_store.hpp"
#include "ui/runs/run_table.hpp"
#include "ui/save_text.hpp"
#include "ui/study/study_view.hpp"

namespace filmdyn::ui {

namespace {

// Undo as a hooked arrow turning back to the left (redo: its mirror), drawn in the text colour:
// the style's back and forward arrows read as a browser's navigation, not as undoing an edit.
QIcon HookedArrowIcon(bool redo, const QColor& colour) {
  QIcon icon;
  for (const int size : {16, 22, 24, 32, 48}) {
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    if (redo) {  // the mirror image
      painter.translate(size, 0);
      painter.scale(-1, 1);
    }
    painter.scale(size / 16.0, size / 16.0);  // drawn on a 16 × 16 grid
    QPen pen(colour, 1.8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    // The hook: from the lower right up round to the left, where the head points back.
    QPainterPath hook;
    hook.moveTo(12.5, 13.0);
    hook.cubicTo(14.5, 8.0, 11.5, 4.5, 7.5, 4.5);
    hook.lineTo(4.5, 4.5);
    painter.drawPath(hook);
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    QPainterPath head;
    head.moveTo(1.0, 4.5);
    head.lineTo(5.5, 0.8);
    head.lineTo(5.5, 8.2);
    head.closeSubpath();
    painter.drawPath(head);
    painter.end();
    icon.addPixmap(pixmap);
  }
  return icon;
}

constexpr int kMaxRecentFiles = 8;
const char* kProjectFilter = QT_TRANSLATE_NOOP("MainWindow", "FilmDyn case (*.json)");

// Why a run with a lubricated joint shows no film fields (empty: none of its joints has a film).
QString NoFieldsReason(const RunRecord& run) {
  if (run.request().model == "ideal") return {};
  if (run.status() == RunStatus::kCancelled)
    return MainWindow::tr("a cancelled run keeps its curves and figures, not its film fields");
  if (run.status() == RunStatus::kRunning) return MainWindow::tr("they appear when the run ends");
  return MainWindow::tr("the run ended before it recorded any");
}

// The film fields of every run in the table, for the field view's "Same scale for all runs".
std::vector<std::shared_ptr<const FieldFrames>> AllRunFields(const std::vector<RunHandle>& runs) {
  std::vector<std::shared_ptr<const FieldFrames>> fields;
  for (const RunHandle& run : runs) fields.push_back(run->fields());
  return fields;
}
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle("FilmDyn");
  setObjectName("MainWindow");
  document_ = new CaseDocument(this);
  engine::EngineCase initial;
  QString error;
  if (!LoadCaseFile({}, &initial, &error)) {
    initial = engine::EngineCase{};
    statusBar()->showMessage(error);
  }
  document_->reset(initial);

  workspace_ = new QTabWidget(this);
  workspace_->setObjectName("workspace");
  workspace_->setDocumentMode(true);
  setCentralWidget(workspace_);
  case_editor_ = new CaseEditor(document_, workspace_);
  workspace_->addTab(case_editor_, tr("Case"));
  run_controller_ = new RunController(this);
  createRunPage();
  field_view_ = new FieldView(workspace_);
  field_view_->setObjectName("field_view");
  workspace_->addTab(field_view_, tr("Pressure fields"));
  study_view_ = new StudyView(workspace_);
  study_view_->setObjectName("study_view");
  workspace_->addTab(study_view_, tr("Study"));
  connect(study_view_, &StudyView::openRunRequested, this, [this](int number) {
    QString error;
    if (!openStudyPointRun(number, &error)) {
      QMessageBox::warning(this, tr("Cannot open the point's run"), error);
    }
  });
  connect(study_view_, &StudyView::statusMessage, this,
          [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(field_view_, &FieldView::crankAngleChanged, plot_panel_, &PlotPanel::setCursorAngle);
  connect(plot_panel_, &PlotPanel::crankAngleClicked, field_view_, &FieldView::setCrankAngle);

  createMenus();
  blocker_label_ = new QLabel(this);
  blocker_label_->setObjectName("run_blocker");
  blocker_label_->setStyleSheet("color: #a00000");
  statusBar()->addPermanentWidget(blocker_label_);
  connect(case_editor_, &CaseEditor::statusMessage, this,
          [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(plot_panel_, &PlotPanel::statusMessage, this,
          [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(document_, &CaseDocument::validityChanged, this, &MainWindow::updateRunActions);
  connect(document_, &CaseDocument::modifiedChanged, this, &MainWindow::updateTitle);
  connect(document_, &CaseDocument::filePathChanged, this, &MainWindow::updateTitle);
  connect(run_controller_, &RunController::runStarted, this, &MainWindow::onRunUpdated);
  connect(run_controller_, &RunController::runUpdated, this, &MainWindow::onRunUpdated);
  connect(run_controller_, &RunController::runFinished, this, &MainWindow::onRunFinished);
  // Autosave: every minute while there are unsaved edits; gone once there are none.
  autosave_ = std::make_unique<AutosaveSlot>();
  autosave_timer_ = new QTimer(this);
  autosave_timer_->setInterval(60 * 1000);
  connect(autosave_timer_, &QTimer::timeout, this, [this] { autosaveNow(); });
  autosave_timer_->start();
  connect(document_, &CaseDocument::modifiedChanged, this, [this](bool modified) {
    if (!modified) autosave_->remove();
  });
  if (statusBar()->currentMessage().isEmpty()) statusBar()->showMessage(tr("Ready"));
  updateRunActions();
  updateTitle();
  restoreWindowState();
}

MainWindow::~MainWindow() {
  // The children (the document, the run controller, the views) are destroyed after this body by
  // ~QWidget; a signal they emit while going (the undo stack's cleanChanged, a run's end) must
  // not reach this half-destroyed window's slots.
  disconnect(document_, nullptr, this, nullptr);
  disconnect(run_controller_, nullptr, this, nullptr);
}

void MainWindow::createRunPage() {
  auto* page = new QWidget(workspace_);
  auto* layout = new QVBoxLayout(page);
  layout->setContentsMargins(0, 0, 0, 0);
  run_splitter_ = new QSplitter(Qt::Vertical, page);
  run_splitter_->setObjectName("run_splitter");
  plot_panel_ = new PlotPanel(run_splitter_);
  run_table_ = new RunTable(run_splitter_);
  run_splitter_->addWidget(plot_panel_);
  run_splitter_->addWidget(run_table_);
  run_splitter_->setStretchFactor(0, 4);
  run_splitter_->setStretchFactor(1, 1);
  // The table holds its header, four runs whole and its scroll bar (at a 1000 px window it showed
  // three and a half, the first cut); the splitter can still fold it away.
  run_table_->setMinimumHeight(run_table_->horizontalHeader()->sizeHint().height() +
                               4 * run_table_->verticalHeader()->defaultSectionSize() +
                               run_table_->horizontalScrollBar()->sizeHint().height() +
                               2 * run_table_->frameWidth() + 2);
  layout->addWidget(run_splitter_);
  connect(run_table_, &RunTable::visibilityToggled, plot_panel_, &PlotPanel::setRunVisible);
  // One label per run (RunRecord::label) in the table, every legend and the field view.
  connect(run_table_, &RunTable::labelsChanged, this, [this](const QList<int>& ids) {
    runs_modified_ = true;
    for (const RunHandle& run : run_table_->runs()) {
      if (!ids.contains(run->id())) continue;
      plot_panel_->setRunLabel(run->id(), run->legendLabel());
      if (run == shown_fields_run_.lock()) showRunFields(*run);
      if (run == state_run_.lock()) showRunState(run);
    }
  });
  connect(run_table_, &RunTable::orderChanged, this, [this](const QList<int>& ids) {
    plot_panel_->setRunOrder(std::vector<int>(ids.begin(), ids.end()));
    runs_modified_ = true;
  });
  connect(run_table_, &RunTable::runsEdited, this, [this] { runs_modified_ = true; });
  connect(run_table_, &RunTable::visibilityToggled, this, [this] { runs_modified_ = true; });
  connect(run_table_, &RunTable::removeRequested, this, &MainWindow::removeRun);
  connect(run_table_, &RunTable::statusMessage, this,
          [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(run_table_, &QTableWidget::currentCellChanged, this, [this] {
    RunHandle run = run_table_->currentRun();
    if (run && run != shown_fields_run_.lock()) {
      shown_fields_run_ = run;
      showRunFields(*run);
    }
  });
  workspace_->addTab(page, tr("Run and results"));
}

void MainWindow::createMenus() {
  auto icon = [this](QStyle::StandardPixmap p) { return style()->standardIcon(p); };
  QMenu* file_menu = menuBar()->addMenu(tr("&File"));
  QAction* new_action = file_menu->addAction(icon(QStyle::SP_FileIcon), tr("&New (default case)"),
                                             this, &MainWindow::newProject);
  new_action->setShortcut(QKeySequence::New);
  QAction* open = file_menu->addAction(icon(QStyle::SP_DialogOpenButton), tr("&Open…"), this,
                                       &MainWindow::openProjectInteractive);
  open->setShortcut(QKeySequence::Open);
  recent_menu_ = file_menu->addMenu(tr("Open &recent"));
  rebuildRecentMenu();
  QAction* save = file_menu->addAction(icon(QStyle::SP_DialogSaveButton), tr("&Save"), this,
                                       &MainWindow::saveProject);
  save->setShortcut(QKeySequence::Save);
  QAction* save_as =
      file_menu->addAction(tr("Save &as…"), this, &MainWindow::saveProjectAsInteractive);
  save_as->setShortcut(QKeySequence::SaveAs);
  file_menu->addSeparator();
  QMenu* export_menu = file_menu->addMenu(tr("&Export"));
  QAction* export_plots = export_menu->addAction(tr("All &plots (PNG, SVG, PDF)…"), this,
                                                 &MainWindow::exportPlotsInteractive);
  export_plots->setShortcut(QKeySequence(tr("Ctrl+E")));
  export_menu->addAction(tr("&Results of the selected run (CSV)…"), this,
                         &MainWindow::exportResultsInteractive);
  export_folder_action_ =
      export_menu->addAction(tr("Run &folder of the selected run (as filmdyn run)…"), this,
                             &MainWindow::exportRunFolderInteractive);
  export_fields_action_ =
      export_menu->addAction(tr("Pressure &fields shown (HDF5 + XDMF for ParaView)…"), this,
                             &MainWindow::exportFieldsInteractive);
  export_menu->addAction(tr("Cylinder pressure curve (CSV)…"), case_editor_,
                         [this] { case_editor_->exportPressureCsv(); });
  QAction* open_study = file_menu->addAction(tr("Open s&tudy folder…"), this, [this] {
    workspace_->setCurrentWidget(study_view_);
    study_view_->openInteractive();
  });
  open_study->setObjectName("open_study_action");
  open_study->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
  open_study->setStatusTip(
      tr("Open the folder of a design study (filmdyn study): its points, "
         "their figures, and any point's run"));
  file_menu->addAction(tr("&Import cylinder pressure (CSV)…"), case_editor_,
                       [this] { case_editor_->importPressureCsv(); });
  file_menu->addSeparator();
  QAction* quit = file_menu->addAction(tr("&Quit"), this, &QWidget::close);
  quit->setShortcut(QKeySequence::Quit);

  QMenu* edit_menu = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = document_->undoStack()->createUndoAction(this, tr("&Undo"));
  undo->setIcon(HookedArrowIcon(false, palette().color(QPalette::WindowText)));
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = document_->undoStack()->createRedoAction(this, tr("&Redo"));
  redo->setIcon(HookedArrowIcon(true, palette().color(QPalette::WindowText)));
  // The platform's redo keys plus Ctrl+Y — once: some platforms' Redo already includes Ctrl+Y,
  // and a key listed twice makes the shortcut ambiguous (it then does nothing).
  QList<QKeySequence> redo_keys = QKeySequence::keyBindings(QKeySequence::Redo);
  if (!redo_keys.contains(QKeySequence(tr("Ctrl+Y")))) redo_keys << QKeySequence(tr("Ctrl+Y"));
  redo->setShortcuts(redo_keys);
  edit_menu->addAction(undo);
  edit_menu->addAction(redo);

  QMenu* run_menu = menuBar()->addMenu(tr("&Run"));
  run_action_ =
      run_menu->addAction(icon(QStyle::SP_MediaPlay), tr("&Run"), this, &MainWindow::startRun);
  run_action_->setShortcuts({QKeySequence(Qt::Key_F5), QKeySequence(tr("Ctrl+R"))});
  cancel_action_ = run_menu->addAction(icon(QStyle::SP_MediaStop), tr("&Cancel run"),
                                       run_controller_, &RunController::cancel);
  cancel_action_->setShortcut(QKeySequence(tr("Shift+F5")));
  run_menu->addAction(tr("Re&move selected run"), this, &MainWindow::removeSelectedRun);

  QMenu* view_menu = menuBar()->addMenu(tr("&View"));
  const QStringList pages = {tr("&Case"), tr("Run and &results"), tr("Pressure &fields"),
                             tr("&Study")};
  for (int i = 0; i < pages.size(); ++i) {
    QAction* a =
        view_menu->addAction(pages[i], this, [this, i] { workspace_->setCurrentIndex(i); });
    a->setShortcut(QKeySequence(QString("Ctrl+%1").arg(i + 1)));
  }

  // The bundled documentation, shown inside the application (ui/help/help_browser).
  QMenu* help_menu = menuBar()->addMenu(tr("&Help"));
  const struct {
    const char* name;
    const char* text;
    const char* page;
  } help_pages[] = {
      {"help_getting_started", QT_TR_NOOP("&Getting started"), "getting-started.md"},
      {"help_user_guide", QT_TR_NOOP("&User guide"), "gui.md"},
      {"help_conventions", QT_TR_NOOP("&Sign conventions"), "conventions.md"},
      {"help_case_fields", QT_TR_NOOP("&Case fields"), "case-file.md"},
      {"help_outputs", QT_TR_NOOP("&Outputs"), "outputs.md"},
  };
  for (const auto& entry : help_pages) {
    const QString page = entry.page;
    QAction* a = help_menu->addAction(tr(entry.text), this, [this, page] { ShowHelp(this, page); });
    a->setObjectName(entry.name);
    if (page == "getting-started.md") a->setShortcut(QKeySequence::HelpContents);
  }
  help_menu
      ->addAction(tr("&All documentation…"), this,
                  [this] { ShowHelp(this, HelpBrowser::kIndexPage); })
      ->setObjectName("help_all");
  help_menu->addSeparator();
  help_menu->addAction(tr("&About FilmDyn"), this, &MainWindow::showAbout);

  QToolBar* toolbar = addToolBar(tr("Main"));
  toolbar->setObjectName("main_toolbar");
  toolbar->setToolButtonStyle(Qt::ToolButtonIconOnly);
  toolbar->addAction(new_action);
  toolbar->addAction(open);
  toolbar->addAction(save);
  toolbar->addSeparator();
  toolbar->addAction(undo);
  toolbar->addAction(redo);
  toolbar->addSeparator();
  toolbar->addAction(run_action_);
  toolbar->addAction(cancel_action_);
  progress_bar_ = new QProgressBar(toolbar);
  progress_bar_->setObjectName("run_progress");
  progress_bar_->setRange(0, 1000);
  progress_bar_->setValue(0);
  progress_bar_->setTextVisible(true);
  progress_bar_->setFormat(tr("idle"));
  progress_bar_->setMaximumWidth(360);
  progress_bar_->setMinimumWidth(260);
  toolbar->addWidget(progress_bar_);
  run_state_label_ = new QLabel(toolbar);
  run_state_label_->setObjectName("run_state");
  run_state_label_->setContentsMargins(8, 0, 8, 0);
  toolbar->addWidget(run_state_label_);
}

void MainWindow::updateTitle() {
  // Plain "FilmDyn" for the untouched default case; otherwise "file * — FilmDyn".
  const bool modified = document_->isModified();
  QString title = "FilmDyn";
  if (!document_->filePath().isEmpty() || modified) {
    const QString file = document_->filePath().isEmpty()
                             ? tr("default case")
                             : QFileInfo(document_->filePath()).fileName();
    title = QString("%1%2 — FilmDyn").arg(file, modified ? " *" : "");
  }
  setWindowTitle(title);
}

void MainWindow::updateRunActions() {
  const QString blocker = document_->runBlocker();
  const bool running = run_controller_->isRunning();
  run_action_->setEnabled(blocker.isEmpty() && !running);
  cancel_action_->setEnabled(running);
  run_action_->setToolTip(blocker.isEmpty() ? tr("Run the case (F5)")
                                            : tr("Cannot run: %1").arg(blocker));
  blocker_label_->setText(blocker.isEmpty() ? QString() : tr("Cannot run: %1").arg(blocker));
  blocker_label_->setToolTip(blocker);
}

void MainWindow::startRun() {
  if (!document_->runBlocker().isEmpty() || run_controller_->isRunning()) return;
  RunRequest request;
  request.engine_case = document_->engineCase();
  request.model = RunModelKey(request.engine_case).toStdString();
  request.rpm = request.engine_case.operating.rpm;
  request.case_directory = document_->caseDirectory();
  RunHandle run = run_controller_->start(std::move(request));
  if (!run) return;
  showRunState(run);
  workspace_->setCurrentIndex(1);
  updateRunActions();
}

void MainWindow::onRunUpdated(const RunHandle& run) {
  run_table_->updateRun(run);  // first: a new run's label says what differs from the base run
  plot_panel_->updateRun(run);
  if (run->status() != RunStatus::kRunning) return;
  const RunProgress p = run->progress();
  const double fraction = p.fraction >= 0 ? p.fraction : p.cycle_fraction;
  progress_bar_->setValue(int(1000 * std::clamp(fraction, 0.0, 1.0)));
  const QString eta =
      p.remaining >= 0 ? tr(", about %1 s left").arg(p.remaining, 0, 'f', 0) : QString();
  if (p.run_in) {
    progress_bar_->setFormat(tr("run-in · %1 °CA, %2 °CA before cycle 1%3")
                                 .arg(p.crank_angle_deg, 0, 'f', 0)
                                 .arg(-720.0 * p.cycle_fraction, 0, 'f', 0)
                                 .arg(eta));
  } else {
    // How far from periodic the last cycle was, once two cycles can be compared.
    const QString change =
        p.cycle_change >= 0 ? tr(" · last change %1 %")
                                  .arg(QString::fromStdString(engine::PercentText(p.cycle_change)))
                            : QString();
    progress_bar_->setFormat(tr("cycle %1 of ≤ %2 · %3 °CA%4%5")
                                 .arg(p.cycle)
                                 .arg(p.max_cycles)
                                 .arg(p.crank_angle_deg, 0, 'f', 0)
                                 .arg(change, eta));
  }
  updateRunActions();
}

void MainWindow::onRunFinished(const RunHandle& run) {
  runs_modified_ = true;
  onRunUpdated(run);
  updateRunActions();
  progress_bar_->setValue(run->status() == RunStatus::kFinished ? 1000 : progress_bar_->value());
  progress_bar_->setFormat(
      tr("%1 (%2 s)").arg(RunStatusText(run->status())).arg(run->elapsedSeconds(), 0, 'f', 2));
  showRunState(run);
  if (run->status() == RunStatus::kFailed) {
    // Inputs stay as they are and the partial results stay in the plots and the table.
    statusBar()->showMessage(
        tr("Run failed: %1 (inputs and partial results kept)").arg(run->reason()));
  } else {
    statusBar()->showMessage(run_state_label_->text(), 10000);
  }
  shown_fields_run_ = run;
  field_view_->setScaleFrames(AllRunFields(run_table_->runs()));
  showRunFields(*run);
}

// The field view on `run`'s fields, titled with its legend label (or why it has none).
void MainWindow::showRunFields(const RunRecord& run) {
  field_view_->setFrames(run.fields(), run.legendLabel(), NoFieldsReason(run));
}

// The toolbar's line on the run last started or finished, in the run's label of the moment (the
// table, the legends and the field view use the same one; relabelling reaches it through
// RunTable::labelsChanged).
void MainWindow::showRunState(const RunHandle& run) {
  state_run_ = run;
  const QString reason = run->reason();
  run_state_label_->setStyleSheet(run->status() == RunStatus::kFailed ? "color: #a00000"
                                                                      : QString());
  if (run->status() == RunStatus::kRunning) {
    run_state_label_->setText(tr("Running %1").arg(run->label()));
  } else {
    run_state_label_->setText(tr("%1 — %2").arg(run->label(), RunStatusText(run->status())) +
                              (reason.isEmpty() ? QString() : QString(": %1").arg(reason)));
  }
  run_state_label_->setToolTip(reason);
}

void MainWindow::removeSelectedRun() {
  RunHandle run = run_table_->currentRun();
  if (!run || run == run_controller_->current()) return;
  removeRun(run->id());
}

void MainWindow::removeRun(int run_id) {
  if (run_controller_->current() && run_controller_->current()->id() == run_id) return;
  plot_panel_->removeRun(run_id);
  run_table_->removeRun(run_id);
  field_view_->setScaleFrames(AllRunFields(run_table_->runs()));
  runs_modified_ = true;
}

void MainWindow::clearRuns() {
  for (const RunHandle& run : std::vector<RunHandle>(run_table_->runs())) {
    if (run != run_controller_->current()) plot_panel_->removeRun(run->id());
  }
  run_table_->removeFinishedRuns();
  field_view_->setScaleFrames(AllRunFields(run_table_->runs()));
  shown_fields_run_.reset();
  field_view_->setFrames(nullptr, QString(), QString());
  runs_modified_ = false;
}

QStringList MainWindow::restoreRuns(const QString& project_path) {
  LoadedRuns loaded = LoadProjectRuns(project_path, [this] { return run_controller_->takeId(); });
  for (const ProjectRun& entry : loaded.runs) {
    run_table_->updateRun(entry.run);
    plot_panel_->updateRun(entry.run);
    if (!entry.visible) run_table_->setRunVisible(entry.run->id(), false);
  }
  if (loaded.base_id >= 0) run_table_->setBaseRun(loaded.base_id);
  field_view_->setScaleFrames(AllRunFields(run_table_->runs()));
  runs_modified_ = false;
  return loaded.problems;
}

bool MainWindow::saveRuns(const QString& project_path, QString* message) {
  std::vector<ProjectRun> runs;
  for (const RunHandle& run : run_table_->runs()) {
    runs.push_back({run, run_table_->isRunVisible(run->id())});
  }
  SaveRunsReport report;
  QString error;
  const bool ok = SaveProjectRuns(project_path, runs, run_table_->baseRunId(), &report, &error);
  if (ok && report.skipped_running == 0) runs_modified_ = false;
  QStringList parts;
  parts << tr("Saved %1 with %n run(s)", nullptr, report.saved).arg(project_path);
  if (report.skipped_running > 0)
    parts << tr("the running run is not saved (save again once it ends)");
  if (report.skipped_unrestored > 0)
    parts << tr("%n run(s) that could not be restored kept as they were saved", nullptr,
                report.skipped_unrestored);
  if (!ok)
    parts = QStringList{tr("Saved the case %1, but not its runs: %2").arg(project_path, error)};
  *message = parts.join("; ");
  return ok;
}

// ---- Projects ----

void MainWindow::newProject() {
  if (!maybeSave()) return;
  engine::EngineCase initial;
  QString error;
  if (!LoadCaseFile({}, &initial, &error)) statusBar()->showMessage(error);
  document_->reset(initial);
  clearRuns();  // the runs belong to the project they were saved with
}

bool MainWindow::openProject(const QString& path, QString* error) {
  QString message;
  if (!document_->load(path, &message)) {
    if (error) *error = message;
    statusBar()->showMessage(message);
    return false;
  }
  addRecentFile(path);
  const QStringList notes = document_->loadNotes();
  if (notes.isEmpty()) {
    statusBar()->showMessage(tr("Opened %1").arg(path), 5000);
  } else {  // e.g. an older key read as its replacement: stays until the next message
    statusBar()->showMessage(tr("Opened %1. Note: %2").arg(path, notes.join(" ")));
  }
  // The project's saved runs replace those of the session; a run that cannot be read back is
  // listed with the reason (the case is open either way).
  clearRuns();
  const QStringList problems = restoreRuns(path);
  if (!problems.isEmpty()) statusBar()->showMessage(problems.join("; "));
  return true;
}

void MainWindow::openProjectInteractive() {
  if (!maybeSave()) return;
  QSettings settings;
  const QString path = QFileDialog::getOpenFileName(
      this, tr("Open case"), settings.value("paths/last_dir").toString(), tr(kProjectFilter));
  if (path.isEmpty()) return;
  settings.setValue("paths/last_dir", QFileInfo(path).absolutePath());
  QString error;
  if (!openProject(path, &error)) QMessageBox::warning(this, tr("Cannot open case"), error);
}

bool MainWindow::openStudyPointRun(int number, QString* error) {
  const batch::StudyRow* row = study_view_->row(number);
  auto fail = [error](const QString& message) {
    if (error) *error = message;
    return false;
  };
  if (row == nullptr) return fail(tr("The open study has no point %1").arg(number));
  const QString folder =
      QDir(study_view_->folder()).filePath(QString::fromStdString(row->point.folder));
  // A point already in the run table is shown, not read twice.
  for (const RunHandle& run : run_table_->runs()) {
    if (!run->storedFolder().isEmpty() && QFileInfo(run->storedFolder()).canonicalFilePath() ==
                                              QFileInfo(folder).canonicalFilePath()) {
      run_table_->selectRow(run_table_->rowOf(run->id()));
      workspace_->setCurrentIndex(workspace_->indexOf(run_splitter_->parentWidget()));
      return true;
    }
  }
  RunRequest request;
  try {
    // The point's case: the study's base case with the point's values (a run folder holds none).
    const io::LoadedCase point = batch::LoadPointCase(study_view_->study(), row->point);
    request.engine_case = point.value;
    request.case_directory = point.directory.string();
    request.model = engine::ModelName(engine::ModelOfCase(request.engine_case));
    request.rpm = request.engine_case.operating.rpm;
  } catch (const std::exception& e) {
    return fail(tr("Point %1: its case cannot be rebuilt from the study: %2")
                    .arg(number)
                    .arg(QString::fromUtf8(e.what())));
  }
  RunHandle run;
  try {
    run = ReadRunFolder(folder, request, run_controller_->takeId());
  } catch (const std::exception& e) {
    return fail(tr("Point %1: %2").arg(number).arg(QString::fromUtf8(e.what())));
  }
  run->setName(
      tr("%1 · point %2").arg(QString::fromStdString(study_view_->study().name)).arg(number));
  run_table_->updateRun(run);
  plot_panel_->updateRun(run);
  field_view_->setScaleFrames(AllRunFields(run_table_->runs()));
  run_table_->selectRow(run_table_->rowOf(run->id()));
  runs_modified_ = true;
  workspace_->setCurrentIndex(workspace_->indexOf(run_splitter_->parentWidget()));
  statusBar()->showMessage(tr("Opened point %1 of the study: %2").arg(number).arg(folder), 8000);
  return true;
}

bool MainWindow::saveProjectAs(const QString& path, QString* error) {
  QString message;
  if (!document_->issues().empty()) {
    // Core refuses such a file; the edits stay here until the cell is fixed.
    message = tr("Not saved: the case has an invalid value (%1). Fix the marked cell first.")
                  .arg(QString::fromStdString(document_->issues().begin()->second));
  } else if (document_->save(path, &message)) {
    addRecentFile(path);
    // The finished runs beside the case (ui/runs/run_store.hpp); running ones are not saved.
    const bool runs_saved = saveRuns(path, &message);
    statusBar()->showMessage(message, runs_saved ? 8000 : 0);
    if (runs_saved) return true;
  }
  if (error) *error = message;
  statusBar()->showMessage(message);
  return false;
}

bool MainWindow::saveProject() {
  if (document_->filePath().isEmpty()) return saveProjectAsInteractive();
  QString error;
  if (saveProjectAs(document_->filePath(), &error)) return true;
  QMessageBox::warning(this, tr("Cannot save case"), error);
  return false;
}

bool MainWindow::saveProjectAsInteractive() {
  QSettings settings;
  QString path = QFileDialog::getSaveFileName(
      this, tr("Save case"),
      QDir(settings.value("paths/last_dir").toString())
          .filePath(QString::fromStdString(document_->engineCase().name) + ".json"),
      tr(kProjectFilter));
  if (path.isEmpty()) return false;
  if (QFileInfo(path).suffix().isEmpty()) path += ".json";
  settings.setValue("paths/last_dir", QFileInfo(path).absolutePath());
  QString error;
  if (saveProjectAs(path, &error)) return true;
  QMessageBox::warning(this, tr("Cannot save case"), error);
  return false;
}

bool MainWindow::hasUnsavedRuns() const {
  if (!runs_modified_) return false;
  for (const RunHandle& run : run_table_->runs()) {
    if (run->status() != RunStatus::kRunning) return true;
  }
  return false;
}

bool MainWindow::maybeSave() {
  const bool case_modified = document_->isModified(), runs_modified = hasUnsavedRuns();
  if (!case_modified && !runs_modified) return true;
  const QString what = case_modified && runs_modified
                           ? tr("The case has unsaved changes and the runs are not saved with the "
                                "project. Save them?")
                       : case_modified
                           ? tr("The case has unsaved changes. Save them?")
                           : tr("The runs (results, names, notes, order) are not saved with the "
                                "project. Save them?");
  const auto answer = QMessageBox::question(
      this, tr("Unsaved changes"), what,
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Cancel) return false;
  if (answer == QMessageBox::Save) return saveProject();
  return true;
}

QStringList MainWindow::recentFiles() const {
  return QSettings().value("recent_files").toStringList();
}

void MainWindow::addRecentFile(const QString& path) {
  QStringList files = recentFiles();
  const QString absolute = QFileInfo(path).absoluteFilePath();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kMaxRecentFiles) files.removeLast();
  QSettings().setValue("recent_files", files);
  rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
  recent_menu_->clear();
  const QStringList files = recentFiles();
  for (int i = 0; i < files.size(); ++i) {
    const QString path = files[i];
    QAction* a =
        recent_menu_->addAction(QString("&%1 %2").arg(i + 1).arg(path), this, [this, path] {
          if (!maybeSave()) return;
          QString error;
          if (!openProject(path, &error)) QMessageBox::warning(this, tr("Cannot open case"), error);
        });
    a->setToolTip(path);
  }
  recent_menu_->setEnabled(!files.isEmpty());
}

// ---- Export ----

bool MainWindow::exportResultsCsv(const RunHandle& run, const QString& path, QString* error,
                                  bool display_units) {
  if (!run) {
    if (error) *error = tr("no run to export");
    return false;
  }
  QByteArray core_csv = run->resultsCsv();
  if (core_csv.isEmpty()) {
    if (error) *error = tr("this run has no results to export yet");
    return false;
  }
  if (display_units) {
    try {
      core_csv = QByteArray::fromStdString(io::ResultsCsvInDisplayUnits(core_csv.toStdString()));
    } catch (const std::exception& e) {
      if (error) *error = QString::fromStdString(e.what());
      return false;
    }
  }
  return SaveTextFile(path, std::string_view(core_csv.constData(), core_csv.size()), error);
}

bool MainWindow::exportRunFolder(const RunHandle& run, const QString& directory, QString* error,
                                 bool replace) {
  if (!run) {
    if (error) *error = tr("no run to export");
    return false;
  }
  // As `filmdyn run --out` takes its folder: locked while written (no other FilmDyn writes
  // there meanwhile), an earlier run's files refused unless replacing them is asked — then
  // exactly FilmDyn's files go and the user's other files stay.
  try {
    const io::OutputFolder folder(
        directory.toStdString(),
        replace ? io::OutputFolder::Reuse::kReplace : io::OutputFolder::Reuse::kRefuse,
        "export folder");
    return run->writeRunFolder(directory, error);
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
}

void MainWindow::exportRunFolderInteractive() {
  RunHandle run = run_table_->currentRun();
  if (!run) {
    statusBar()->showMessage(tr("No run to export yet"), 5000);
    return;
  }
  QSettings settings;
  const QString dir = QFileDialog::getExistingDirectory(
      this, tr("Write the run folder into"), settings.value("paths/export_dir").toString());
  if (dir.isEmpty()) return;
  settings.setValue("paths/export_dir", dir);
  bool replace = false;
  if (io::OutputFolder::HoldsEarlierRun(dir.toStdString())) {
    const auto answer = QMessageBox::question(
        this, tr("Replace the earlier run?"),
        tr("%1 holds the files of an earlier run (results.csv, summary.json, …). Replace them? "
           "Only FilmDyn's files are replaced; your other files there stay.")
            .arg(QDir::toNativeSeparators(dir)),
        QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Yes) return;
    replace = true;
  }
  startRunFolderExport(run, dir, replace);
}

bool MainWindow::isExporting() const { return export_watcher_ != nullptr; }

void MainWindow::startRunFolderExport(const RunHandle& run, const QString& directory,
                                      bool replace) {
  exportInBackground(tr("Writing the run folder to %1…").arg(directory), [run, directory, replace](
                                                                             QString* message) {
    if (!exportRunFolder(run, directory, message, replace)) return false;
    *message =
        QFileInfo::exists(QDir(directory).filePath("fields"))
            ? tr("Wrote the run folder (results.csv, summary.json, fields/) to %1").arg(directory)
            : tr("Wrote the run folder (results.csv, summary.json; no fields/: the run kept "
                 "none) to %1")
                  .arg(directory);
    return true;
  });
}

void MainWindow::startFieldsExport(const RunHandle& run, const QString& directory) {
  exportInBackground(tr("Writing the fields to %1…").arg(directory),
                     [run, directory](QString* message) {
                       if (!run->writeFields(directory, message)) return false;
                       *message = tr("Wrote fields to %1").arg(directory);
                       return true;
                     });
}

void MainWindow::exportInBackground(const QString& busy,
                                    std::function<bool(QString* message)> job) {
  if (export_watcher_ != nullptr) return;  // the actions are disabled meanwhile
  export_watcher_ = new QFutureWatcher<std::pair<bool, QString>>(this);
  export_folder_action_->setEnabled(false);
  export_fields_action_->setEnabled(false);
  statusBar()->showMessage(busy);
  connect(export_watcher_, &QFutureWatcherBase::finished, this, &MainWindow::finishExport);
  export_watcher_->setFuture(QtConcurrent::run([job = std::move(job)] {
    QString message;
    bool ok = false;
    try {
      ok = job(&message);
    } catch (const std::exception& e) {
      message = QString::fromUtf8(e.what());
    }
    return std::pair<bool, QString>(ok, message);
  }));
}

void MainWindow::finishExport() {
  if (export_watcher_ == nullptr) return;
  const auto [ok, message] = export_watcher_->result();
  export_watcher_->deleteLater();
  export_watcher_ = nullptr;
  export_folder_action_->setEnabled(true);
  export_fields_action_->setEnabled(true);
  statusBar()->showMessage(ok ? message : tr("Export failed: %1").arg(message), ok ? 8000 : 0);
  emit exportFinished(ok, message);
  if (!ok) QMessageBox::warning(this, tr("Export failed"), message);
}

bool MainWindow::exportAllPlots(const QString& directory, const QStringList& suffixes,
                                QString* error) {
  if (!QDir().mkpath(directory)) {
    if (error) *error = tr("Cannot create %1").arg(directory);
    return false;
  }
  for (int i = 0; i < plot_panel_->chartCount(); ++i) {
    for (const QString& suffix : suffixes) {
      const QString path = QDir(directory).filePath(plot_panel_->chartId(i) + "." + suffix);
      ImageFormat format;
      if (!FormatFromSuffix(path, &format)) {
        if (error) *error = tr("unknown image format: %1").arg(suffix);
        return false;
      }
      if (!plot_panel_->exportChart(i, path, format, QSize(960, 600), error)) return false;
    }
  }
  return true;
}

void MainWindow::exportPlotsInteractive() {
  QSettings settings;
  const QString dir = QFileDialog::getExistingDirectory(
      this, tr("Export all plots to"), settings.value("paths/export_dir").toString());
  if (dir.isEmpty()) return;
  settings.setValue("paths/export_dir", dir);
  bool ok = false;
  const QStringList choices = {"png, svg, pdf", "png", "svg", "pdf"};
  const QString last = settings.value("export/formats", choices.first()).toString();
  const QString chosen = QInputDialog::getItem(this, tr("Export plots"), tr("Formats:"), choices,
                                               std::max(0, int(choices.indexOf(last))), false, &ok);
  if (!ok) return;
  settings.setValue("export/formats", chosen);
  QStringList suffixes = chosen.split(", ");
  QString error;
  if (exportAllPlots(dir, suffixes, &error)) {
    statusBar()->showMessage(tr("Wrote %1 plots to %2").arg(plot_panel_->chartCount()).arg(dir),
                             8000);
  } else {
    QMessageBox::warning(this, tr("Export failed"), error);
  }
}

void MainWindow::exportResultsInteractive() {
  RunHandle run = run_table_->currentRun();
  if (!run) {
    statusBar()->showMessage(tr("No run to export yet"), 5000);
    return;
  }
  QSettings settings;
  const QString si = tr("CSV in SI units, as results.csv (*.csv)");
  const QString display = tr("CSV in display units: µm, mrad, kN, MPa, bar (*.csv)");
  QString filter = settings.value("paths/results_units").toString() == "display" ? display : si;
  // A run that did not end normally offers a name that says so: its rows are partial.
  const QString state =
      run->status() == RunStatus::kFinished ? QString() : RunStatusText(run->status());
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Export results"),
      QDir(settings.value("paths/export_dir").toString())
          .filePath(state.isEmpty() ? QString("results.csv")
                                    : QString("results-%1.csv").arg(state)),
      si + ";;" + display, &filter);
  if (path.isEmpty()) return;
  settings.setValue("paths/export_dir", QFileInfo(path).absolutePath());
  settings.setValue("paths/results_units", filter == display ? "display" : "si");
  QString error;
  if (exportResultsCsv(run, path, &error, filter == display)) {
    statusBar()->showMessage(state.isEmpty()
                                 ? tr("Wrote %1").arg(path)
                                 : tr("Wrote %1 — partial results: the run is %2").arg(path, state),
                             8000);
  } else {
    QMessageBox::warning(this, tr("Export failed"), error);
  }
}

void MainWindow::exportFieldsInteractive() {
  const RunHandle run = shown_fields_run_.lock();
  const FieldFrames* frames = field_view_->frames();
  if (!run || !frames || frames->empty()) {
    statusBar()->showMessage(
        tr("No pressure fields to export: only runs with a lubricated joint have them"), 8000);
    return;
  }
  const QString dir = QFileDialog::getExistingDirectory(this, tr("Export fields to"));
  if (dir.isEmpty()) return;
  // Files of those names there (another run's fields, or anything of the user's) are replaced
  // only when the user says so.
  QStringList there;
  for (const char* name : {"skirt.h5", "skirt.xdmf", "bearing.h5", "bearing.xdmf"})
    if (QFileInfo::exists(QDir(dir).filePath(name))) there << name;
  if (!there.isEmpty()) {
    const auto answer =
        QMessageBox::question(this, tr("Replace files?"),
                              tr("%1 holds %2. Replace them with this run's fields?")
                                  .arg(QDir::toNativeSeparators(dir), there.join(", ")),
                              QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Yes) return;
  }
  startFieldsExport(run, dir);
}

// ---- Window ----

void MainWindow::showAbout() {
  QString text =
      tr("<h3>FilmDyn</h3><p>Engine dynamics with lubricated piston skirt and big-end "
         "bearing: secondary motion, journal orbit, film thickness, friction.</p><table>");
  for (const auto& [name, version] : LibraryVersions()) {
    text += QString("<tr><td>%1</td><td>&nbsp;%2</td></tr>")
                .arg(QString::fromStdString(name), QString::fromStdString(version));
  }
  text += "</table>";
  QMessageBox::about(this, tr("About FilmDyn"), text);
}

void MainWindow::restoreWindowState() {
  QSettings settings;
  if (!restoreGeometry(settings.value("main_window/geometry").toByteArray())) resize(1280, 820);
  restoreState(settings.value("main_window/state").toByteArray());
  run_splitter_->restoreState(settings.value("main_window/run_splitter").toByteArray());
  workspace_->setCurrentIndex(settings.value("main_window/tab", 0).toInt());
}

QString MainWindow::autosavePath() const { return autosave_->filePath(); }

bool MainWindow::hasRecovery() { return !ClaimLeftAutosaves().empty(); }

bool MainWindow::autosaveNow(QString* error) {
  if (!document_->isModified()) {
    autosave_->remove();
    return true;
  }
  QString message;
  if (!autosave_->write(document_->engineCase(), document_->filePath(), &message)) {
    if (error) *error = message;
    statusBar()->showMessage(tr("Autosave failed: %1").arg(message), 8000);
    return false;
  }
  return true;
}

bool MainWindow::recoverAutosave(const LeftAutosave& left, QString* error) {
  engine::EngineCase base;
  QString ignored;
  if (left.source.isEmpty() || !LoadCaseFile(left.source, &base, &ignored)) {
    if (!LoadCaseFile({}, &base, &ignored)) base = engine::EngineCase{};
  }
  // The autosave holds the case as it was, marked cells included: what the reader refuses takes
  // the saved case's value, and everything else is recovered.
  engine::EngineCase recovered;
  std::vector<std::string> dropped;
  try {
    recovered = io::CaseFileKeepingValid(left.file.toStdString(), base, &dropped);
  } catch (const std::exception& e) {
    if (error) *error = tr("%1: %2").arg(left.file, QString::fromUtf8(e.what()));
    return false;
  }
  document_->reset(
      base, left.source.isEmpty() || !QFileInfo::exists(left.source) ? QString() : left.source);
  document_->edit(recovered, tr("Recovered unsaved edits"));
  // In this window's own file at once; the left one goes only once that is written.
  if (autosaveNow()) left.remove();
  QString message = tr("Recovered the unsaved edits of the last session");
  if (!dropped.empty()) {
    QStringList lines;
    for (const std::string& d : dropped) lines << QString::fromStdString(d);
    // Stays until the next message: these edits are not back.
    message += tr("; %n value(s) marked invalid then kept the saved value: %1", nullptr,
                  int(dropped.size()))
                   .arg(lines.join("; "));
    statusBar()->showMessage(message);
  } else {
    statusBar()->showMessage(message, 8000);
  }
  return true;
}

void MainWindow::offerRecovery() {
  const std::vector<LeftAutosave> left = ClaimLeftAutosaves();
  for (std::size_t i = 0; i < left.size(); ++i) {
    const LeftAutosave& one = left[i];
    const QString belongs = one.source.isEmpty()
                                ? tr("a case not yet saved")
                                : tr("the case %1").arg(QDir::toNativeSeparators(one.source));
    QString question =
        tr("FilmDyn did not close normally last time. Restore the unsaved edits of %1 (saved "
           "automatically %2)?")
            .arg(belongs, QLocale().toString(one.written, QLocale::ShortFormat));
    if (left.size() > 1) {
      question += tr("\n\n(%1 of %2 sessions that did not close normally, the newest first.)")
                      .arg(i + 1)
                      .arg(left.size());
    }
    const auto answer =
        QMessageBox::question(this, tr("Recover unsaved edits"), question,
                              QMessageBox::Yes | QMessageBox::Discard, QMessageBox::Yes);
    if (answer != QMessageBox::Yes) {
      one.remove();
      continue;
    }
    QString error;
    if (recoverAutosave(one, &error)) {
      if (const std::size_t waiting = left.size() - i - 1; waiting > 0) {
        // This window holds one case; the others are offered by the next FilmDyn started.
        statusBar()->showMessage(
            statusBar()->currentMessage() +
            tr(". %n more session(s) left unsaved edits: start FilmDyn again to recover them",
               nullptr, int(waiting)));
      }
      return;
    }
    // Kept aside (its name is this window's no more: it would be offered at every start).
    const QString kept = NotRecoveredPath(one);
    QFile::remove(kept);
    const bool moved = QFile::rename(one.file, kept);
    if (moved) one.remove();
    QMessageBox::warning(this, tr("Cannot recover"),
                         moved ? tr("%1\n\nThe file is kept as %2.").arg(error, kept) : error);
  }
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (run_controller_->isRunning()) {
    // A run in progress is not dropped silently: asked first; if stopped, the window closes once
    // the run has ended (within about a second), through the question about its unsaved results.
    event->ignore();
    if (closing_after_run_) return;  // asked already: the run is stopping
    const auto answer = QMessageBox::question(
        this, tr("Run in progress"),
        tr("A run is in progress. Stop it and close FilmDyn?\n\nWhat it has computed so far is "
           "kept as a cancelled run, which you can then save with the project."),
        QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel);
    if (answer != QMessageBox::Yes || !run_controller_->isRunning()) {
      if (answer == QMessageBox::Yes) QTimer::singleShot(0, this, &QWidget::close);
      return;
    }
    closing_after_run_ = true;
    connect(
        run_controller_, &RunController::runFinished, this,
        [this] {
          closing_after_run_ = false;
          QTimer::singleShot(0, this, &QWidget::close);
        },
        Qt::SingleShotConnection);
    run_controller_->cancel();
    return;
  }
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  if (export_watcher_ != nullptr) {
    // An export under way ends before the window goes (its files whole, a failure said).
    statusBar()->showMessage(tr("Waiting for the export to end…"));
    export_watcher_->waitForFinished();
    finishExport();
  }
  autosave_->remove();  // saved or discarded: nothing to recover
  QSettings settings;
  settings.setValue("main_window/geometry", saveGeometry());
  settings.setValue("main_window/state", saveState());
  settings.setValue("main_window/run_splitter", run_splitter_->saveState());
  settings.setValue("main_window/tab", workspace_->currentIndex());
  event->accept();
}

}  // namespace filmdyn::ui
