#pragma once
/// @file The study page: a study folder (`filmdyn study`, docs/study.md) opened in the GUI. A
/// sortable table of its points — the factors' values, the state and status of each run, its
/// figures — read from the points' folders in a worker thread (a study of thousands of points
/// never blocks the window) and read again while points are still pending or running; a
/// scatter plot of any figure against any factor, where clicking a point selects its row; and
/// opening a point's run in the results view (openRunRequested).
#include <QFutureWatcher>
#include <QWidget>
#include <vector>

#include "core/batch/study.hpp"

class QAbstractTableModel;
class QChartView;
class QComboBox;
class QLabel;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;
class QTimer;

namespace filmdyn::ui {

class StudyView : public QWidget {
  Q_OBJECT

 public:
  explicit StudyView(QWidget* parent = nullptr);
  ~StudyView() override;

  /// Opens the study folder `dir`: its study.json is read at once (false with *error naming the
  /// file when it is not a study folder); the points' folders are read in the background
  /// (loaded() when done). A read of the folder open before, still under way, is not waited
  /// for: its rows are dropped when it ends, and the new folder is read then.
  bool openFolder(const QString& dir, QString* error = nullptr);
  /// Reads the points' folders again (nothing when no study is open or a read is under way).
  void reload();
  /// Whether the points' folders are being read.
  bool isLoading() const;

  QString folder() const { return folder_; }
  const batch::Study& study() const { return study_; }
  /// The points as last read, in design order.
  const std::vector<batch::StudyRow>& rows() const { return rows_; }
  /// The row of point `number` in rows(), or nullptr.
  const batch::StudyRow* row(int number) const;

  /// Selects point `number` in the table (and marks it in the scatter plot).
  void selectPoint(int number);
  /// The point selected in the table (0 for none).
  int selectedPoint() const;
  /// Sets the scatter plot's axes: factor index (study().factors) and figure index
  /// (io::ComparisonFigures); false when either is not offered.
  bool setScatter(int factor, int figure);

  QTableView* table() const { return table_; }
  QComboBox* factorBox() const { return factor_box_; }
  QComboBox* figureBox() const { return figure_box_; }
  QChartView* scatterView() const { return scatter_view_; }
  QPushButton* openRunButton() const { return open_run_button_; }

 public slots:
  /// Asks for a study folder and opens it.
  void openInteractive();

 signals:
  /// The points' folders have been read (rows() holds them).
  void loaded();
  /// The user asked to see point `number`'s run in the results view.
  void openRunRequested(int number);
  void statusMessage(const QString& message);

 private:
  void onLoaded();
  void rebuildScatter();
  void markSelection();
  void fitLastColumn();
  static constexpr int kLastColumnWidth = 420;  ///< [px] the reasons' and notes' column at most
  void requestOpenRun();

  QString folder_;
  batch::Study study_;
  std::vector<batch::StudyRow> rows_;
  /// Indices of io::ComparisonFigures that some point has (the figure box's entries).
  std::vector<int> figures_;
  QFutureWatcher<std::pair<std::vector<batch::StudyRow>, QString>>* watcher_ = nullptr;
  /// Counts the folders opened; the read under way is of folder number read_folder_.
  int opened_folder_ = 0;
  int read_folder_ = 0;

  QLabel* title_ = nullptr;
  QLabel* counts_ = nullptr;
  QPushButton* reload_button_ = nullptr;
  QPushButton* open_run_button_ = nullptr;
  QAbstractTableModel* model_ = nullptr;
  QSortFilterProxyModel* proxy_ = nullptr;
  QTableView* table_ = nullptr;
  QComboBox* factor_box_ = nullptr;
  QComboBox* figure_box_ = nullptr;
  QChartView* scatter_view_ = nullptr;
  QTimer* refresh_timer_ = nullptr;
};

}  // namespace filmdyn::ui
