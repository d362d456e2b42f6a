#pragma once
/// @file The steady skirt calculator on the case editor's skirt tab: the film of the case's skirt
/// at a state the user sets (e0, tilt, rates, speed) or under a load (side force, moment, speed),
/// computed in the background as the inputs or the case change (the same core calculator as
/// `filmdyn skirt`), with every reported quantity in a table and the unrolled film map.
#include <QFutureWatcher>
#include <QWidget>
#include <atomic>
#include <map>
#include <memory>
#include <optional>

#include "core/lubrication/skirt_calculator.hpp"
#include "ui/charts/film_map_widget.hpp"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTableWidget;
class QTimer;

namespace filmdyn::ui {

class CaseDocument;

/// What one background calculation returns.
struct SkirtCalculation {
  bool ok = false;
  QString message;  ///< the error (bad input, no equilibrium) or how the equilibrium was found
  lubrication::SkirtPoint point;
  // The whole skirt's nodal fields on its tensor grid: α [°] × y [mm], node (i, j) at i + nx j.
  std::vector<double> alpha_deg, y_mm, pressure_mpa, film_um, contact_mpa;
  std::vector<std::pair<double, double>> relief_deg;
};

class SkirtCalculatorPanel : public QWidget {
  Q_OBJECT

 public:
  enum class Mode { kState, kLoad };
  explicit SkirtCalculatorPanel(CaseDocument* document, QWidget* parent = nullptr);
  ~SkirtCalculatorPanel() override;

  QComboBox* modeSelector() const { return mode_; }
  /// The input boxes by key: e0, tilt, e0_rate, tilt_rate, speed, side_force, moment (display
  /// units as labelled).
  QDoubleSpinBox* input(const std::string& key) const { return inputs_.at(key); }
  QComboBox* mapSelector() const { return map_quantity_; }
  QTableWidget* resultTable() const { return table_; }
  QLabel* statusLabel() const { return status_; }
  FilmMapWidget* filmMap() const { return map_; }
  /// The last calculation shown (none before the first finishes).
  const std::optional<SkirtCalculation>& last() const { return last_; }
  /// A calculation is waiting or running.
  bool busy() const;

 signals:
  /// A calculation finished and its result (or error) is shown.
  void updated();

 private:
  void showResultsCurrent(bool current);
  void schedule();
  void start();
  void finished();
  void showMap();
  void updateModeInputs();

  CaseDocument* document_;
  QComboBox* mode_ = nullptr;
  QComboBox* map_quantity_ = nullptr;
  std::map<std::string, QDoubleSpinBox*> inputs_;
  std::map<std::string, QWidget*> input_rows_;
  QTableWidget* table_ = nullptr;
  QLabel* status_ = nullptr;
  FilmMapWidget* map_ = nullptr;
  QTimer* debounce_ = nullptr;
  QFutureWatcher<SkirtCalculation> watcher_;
  std::shared_ptr<std::atomic<bool>> cancel_;
  bool running_ = false;  ///< started, its result not shown yet
  bool pending_ = false;  ///< inputs changed while a calculation ran: start again when it ends
  std::optional<SkirtCalculation> last_;
};

}  // namespace filmdyn::ui
