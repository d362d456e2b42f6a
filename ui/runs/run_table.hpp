#pragma once
/// @file The runs of the session side by side: a checkbox to show or hide each in the plots,
/// the run's name (editable; by default what differs from the base run), those differences,
/// status (with the reason of a failure), the main figures of each, and the user's notes
/// (editable). The context menu marks the base run, renames, moves and removes runs.
#include <QHash>
#include <QTableWidget>
#include <vector>

#include "ui/run/run_record.hpp"

namespace filmdyn::ui {

class RunTable : public QTableWidget {
  Q_OBJECT

 public:
  enum ColumnIndex {
    kShow,
    kRun,
    kDifferences,
    kStatus,
    kWarnings,
    kCycles,
    kWall,
    kLateral,
    kTilt,
    kSkirtMoft,
    kBearingMoft,
    kSkirtFpl,
    kBearingFpl,
    kSkirtFmep,
    kBearingFmep,
    kSkirtOil,
    kBearingOil,
    kBigEndForce,
    kError,
    kNotes,
    kReason,
    kColumns
  };

  explicit RunTable(QWidget* parent = nullptr);

  /// Adds the run (first call) or refreshes its row.
  void updateRun(const RunHandle& run);
  void removeRun(int run_id);
  /// The selected run, else the newest one, else nullptr.
  RunHandle currentRun() const;
  const std::vector<RunHandle>& runs() const { return runs_; }
  int rowOf(int run_id) const;

  /// The run the others' automatic labels say their differences from: the one marked "Use as
  /// base run", else the first in the table (-1 without runs).
  int baseRunId() const;
  void setBaseRun(int run_id);
  /// Gives the run a name (empty = its automatic label). False with *error when another run
  /// already has that label (labels are unique).
  bool renameRun(int run_id, const QString& name, QString* error = nullptr);
  void setRunNotes(int run_id, const QString& notes);
  /// Moves a run up (delta < 0) or down in the table; the plots follow (orderChanged).
  void moveRun(int run_id, int delta);
  /// Ticks or clears the run's Show box (emits visibilityToggled).
  void setRunVisible(int run_id, bool visible);
  bool isRunVisible(int run_id) const;
  /// Removes every run that is not running.
  void removeFinishedRuns();
  /// Recomputes every run's differences from the base run and its automatic label (unique
  /// among the runs), and refreshes the name cells; emits labelsChanged when a label changed.
  void relabel();

 signals:
  void visibilityToggled(int run_id, bool visible);
  /// Some runs' labels (RunRecord::label) changed: legends and titles showing them are stale.
  void labelsChanged(const QList<int>& run_ids);
  /// The runs' order changed (ids, top to bottom).
  void orderChanged(const QList<int>& run_ids);
  /// The user asked to remove the run (context menu).
  void removeRequested(int run_id);
  /// A run's notes changed (what a saved project keeps besides labels, order and visibility).
  void runsEdited();
  void statusMessage(const QString& message);

 protected:
  void contextMenuEvent(QContextMenuEvent* event) override;

 private:
  void fillIdentity(int row);
  QList<int> orderIds() const;

  std::vector<RunHandle> runs_;
  bool updating_ = false;
  int base_id_ = -1;                     ///< the run marked as base (-1: the first run)
  QHash<int, QString> shown_labels_;     ///< each run's label when labelsChanged last told it
  QHash<int, QString> difference_tips_;  ///< per run: each difference with both values
};

}  // namespace filmdyn::ui
