#pragma once
/// @file The runs of the session side by side: a checkbox to show or hide each in the plots,
/// status (with the reason of a failure), and the main figures of each.
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
    kStatus,
    kCycles,
    kWall,
    kLateral,
    kTilt,
    kSkirtMoft,
    kBearingMoft,
    kSkirtFpl,
    kBearingFpl,
    kBigEndForce,
    kError,
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

 signals:
  void visibilityToggled(int run_id, bool visible);

 private:
  std::vector<RunHandle> runs_;
  bool updating_ = false;
};

}  // namespace filmdyn::ui
