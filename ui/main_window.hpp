#pragma once
/// @file The FilmDyn main window: the case editor, the run page (Run/Cancel, progress, live plots
/// overlaid for every run of the session, the run comparison table) and the pressure-field view;
/// menus and shortcuts; project files with recent files and an unsaved-changes prompt. Window
/// geometry, state and preferences are remembered between sessions (QSettings).
#include <QFutureWatcher>
#include <QMainWindow>
#include <QStringList>
#include <functional>
#include <memory>
#include <utility>

#include "ui/run/run_record.hpp"

class QAction;
class QLabel;
class QMenu;
class QProgressBar;
class QSplitter;
class QTabWidget;
class QTimer;

namespace filmdyn::ui {

class AutosaveSlot;
struct LeftAutosave;
class CaseDocument;
class CaseEditor;
class FieldView;
class PlotPanel;
class RunController;
class RunTable;
class StudyView;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  QTabWidget* workspace() const { return workspace_; }
  CaseDocument* document() const { return document_; }
  CaseEditor* caseEditor() const { return case_editor_; }
  RunController* runController() const { return run_controller_; }
  PlotPanel* plotPanel() const { return plot_panel_; }
  RunTable* runTable() const { return run_table_; }
  FieldView* fieldView() const { return field_view_; }
  StudyView* studyView() const { return study_view_; }
  QAction* runAction() const { return run_action_; }
  QAction* cancelAction() const { return cancel_action_; }
  QProgressBar* progressBar() const { return progress_bar_; }
  QLabel* runStateLabel() const { return run_state_label_; }
  QStringList recentFiles() const;

  /// Non-interactive operations (menus call them after asking; tests and scripts call directly).
  bool openProject(const QString& path, QString* error = nullptr);
  bool saveProjectAs(const QString& path, QString* error = nullptr);
  /// results.csv in core's format (as `filmdyn run` writes it; columns as in docs/outputs.md).
  /// results.csv of a run, in SI (byte for byte core's file) or in display units (µm, kN, MPa, ...:
  /// the units of the plots and the run table, ASCII in the header, e.g. "skirt_moft[um]").
  bool exportResultsCsv(const RunHandle& run, const QString& path, QString* error = nullptr,
                        bool display_units = false);
  /// The run's output folder exactly as `filmdyn run --out DIR` writes it (results.csv,
  /// summary.json, fields/), the folder taken as that command takes it: locked while written, a
  /// folder holding an earlier run's files refused (false, *error naming it) unless `replace`,
  /// which removes exactly FilmDyn's files of it first.
  static bool exportRunFolder(const RunHandle& run, const QString& directory,
                              QString* error = nullptr, bool replace = false);
  /// Unsaved edits are written every minute to autosavePath(), this window's own file (with the
  /// case file they belong to beside it: ui/autosave.hpp), and the file is removed once they are
  /// saved or discarded or the window closes normally; after a crash the next start offers them
  /// back (offerRecovery). Windows open at once each have their own file.
  QString autosavePath() const;
  /// Whether the session's runs differ from what the project file's runs folder holds.
  bool hasUnsavedRuns() const;
  /// Writes the autosave now when the case has unsaved edits (removes it when it has none).
  bool autosaveNow(QString* error = nullptr);
  /// An autosave of a window that is gone is waiting (it did not close normally).
  static bool hasRecovery();
  /// Adds the run of point `number` of the study the Study page shows to the runs (its folder
  /// read by ReadRunFolder, its case rebuilt from the study) and shows the results page; a
  /// point already among the runs is selected. False with *error saying why it cannot be read.
  bool openStudyPointRun(int number, QString* error = nullptr);
  /// The run-folder and fields exports write on a worker thread (tens of MB of HDF5 on fine
  /// meshes, each file synced): the window stays responsive, those two exports wait (disabled)
  /// until the one under way ends, and exportFinished reports it (the status bar says it, a
  /// message box says why it failed). Closing the window waits for it to end.
  bool isExporting() const;
  /// exportRunFolder on the worker thread (the interactive export, its questions answered).
  void startRunFolderExport(const RunHandle& run, const QString& directory, bool replace);
  /// The run's fields/ files into `directory` on the worker thread.
  void startFieldsExport(const RunHandle& run, const QString& directory);
  /// Writes every plot as <dir>/<plot id>.<suffix> for each suffix in {png, svg, pdf}.
  bool exportAllPlots(const QString& directory, const QStringList& suffixes,
                      QString* error = nullptr);

 signals:
  /// A background export ended: `message` is what the status bar shows, or why it failed.
  void exportFinished(bool ok, const QString& message);

 public slots:
  void showAbout();
  void startRun();
  void newProject();
  void openProjectInteractive();
  bool saveProject();
  bool saveProjectAsInteractive();
  void exportPlotsInteractive();
  void exportResultsInteractive();
  void exportFieldsInteractive();
  void exportRunFolderInteractive();
  void removeSelectedRun();
  /// Removes a run from the table and the plots (not the one running).
  void removeRun(int run_id);
  /// Asks whether to restore the waiting autosaves, newest first, until one is restored (main()
  /// calls it once the window is shown); the others wait for the next start.
  void offerRecovery();

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void createRunPage();
  void createMenus();
  void restoreWindowState();
  void updateTitle();
  void updateRunActions();
  void addRecentFile(const QString& path);
  void rebuildRecentMenu();
  /// Asks to save unsaved edits of the case or runs not yet saved with the project; false when
  /// the user cancels.
  bool maybeSave();
  /// Loads `left` as unsaved edits on top of its case file (or the default case), writes this
  /// window's autosave and removes `left`.
  bool recoverAutosave(const LeftAutosave& left, QString* error);
  void onRunUpdated(const RunHandle& run);
  /// Project runs (ui/runs/run_store.hpp): drops the session's finished runs; reads back those
  /// saved beside `project_path` (returns what could not be restored); saves the finished runs
  /// beside it (*message says what was saved and what not).
  void clearRuns();
  QStringList restoreRuns(const QString& project_path);
  bool saveRuns(const QString& project_path, QString* message);
  /// Something about the runs the project would save changed since it was last saved or opened:
  /// a run finished, was removed, renamed, annotated, re-ordered, hidden or made the base.
  bool runs_modified_ = false;
  void onRunFinished(const RunHandle& run);
  /// Runs `job` (which says what it wrote, or why not) on a worker thread as described at
  /// isExporting(); `busy` is the status bar's text meanwhile.
  void exportInBackground(const QString& busy, std::function<bool(QString* message)> job);
  void finishExport();
  void showRunState(const RunHandle& run);
  void showRunFields(const RunRecord& run);

  QTabWidget* workspace_ = nullptr;
  CaseDocument* document_ = nullptr;
  CaseEditor* case_editor_ = nullptr;
  RunController* run_controller_ = nullptr;
  PlotPanel* plot_panel_ = nullptr;
  RunTable* run_table_ = nullptr;
  FieldView* field_view_ = nullptr;
  StudyView* study_view_ = nullptr;
  QSplitter* run_splitter_ = nullptr;
  QAction* run_action_ = nullptr;
  QAction* cancel_action_ = nullptr;
  QMenu* recent_menu_ = nullptr;
  QProgressBar* progress_bar_ = nullptr;
  QLabel* run_state_label_ = nullptr;
  QLabel* blocker_label_ = nullptr;
  QTimer* autosave_timer_ = nullptr;
  std::unique_ptr<AutosaveSlot> autosave_;
  QAction* export_folder_action_ = nullptr;
  QAction* export_fields_action_ = nullptr;
  /// The background export under way (nullptr when none): its result, once ended.
  QFutureWatcher<std::pair<bool, QString>>* export_watcher_ = nullptr;
  bool closing_after_run_ = false;  ///< a close asked to stop the run; it closes when it ends
  std::weak_ptr<RunRecord> shown_fields_run_;  ///< the run whose fields the field page shows
  std::weak_ptr<RunRecord> state_run_;         ///< the run the toolbar's state line speaks of
};

}  // namespace filmdyn::ui
