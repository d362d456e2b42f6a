#include "ui/case_editor/skirt_calculator_panel.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/base/stop.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/skirt_report.hpp"
#include "ui/case_editor/case_document.hpp"

namespace filmdyn::ui {

namespace {

struct InputSpec {
  std::string key;
  QString label;  ///< with the display unit
  double scale;   ///< display value × scale = SI
  double lo, hi, value;
  int decimals;
  QString tip;
};

const std::vector<InputSpec>& InputSpecs() {
  static const std::vector<InputSpec> specs = {
      {"e0", "e0 [µm]", 1e-6, -1000, 1000, 10, 3,
       "Lateral displacement of the piston axis at the pin, + toward the thrust side"},
      {"tilt", "Tilt [mrad]", 1e-3, -100, 100, 0.2, 4,
       "Piston tilt, + moves the skirt below the pin toward the thrust side"},
      {"e0_rate", "de0/dt [mm/s]", 1e-3, -10000, 10000, 0, 3,
       "Lateral velocity of the piston axis at the pin (squeeze)"},
      {"tilt_rate", "Tilt rate [rad/s]", 1.0, -10000, 10000, 0, 4, "Rate of the tilt (squeeze)"},
      {"speed", "Speed [m/s]", 1.0, -200, 200, 10, 3,
       "Piston speed along the skirt axis, + toward the crank (results' piston velocity is + "
       "toward the head)"},
      {"side_force", "Side force [N]", 1.0, -1e7, 1e7, 1000, 1,
       "Lateral force the rest of the engine applies to the piston, + toward the thrust side; "
       "the film must balance it"},
      {"moment", "Moment [N·m]", 1.0, -1e6, 1e6, 0, 3,
       "Moment applied to the piston about the pin, + turns the skirt bottom toward thrust"}};
  return specs;
}

// An input's label without its unit ("Tilt" of "Tilt [mrad]"), and the unit ("mrad").
std::string NameOf(const InputSpec& spec) {
  return spec.label.left(spec.label.lastIndexOf(" [")).toStdString();
}
QString UnitOf(const InputSpec& spec) {
  return spec.label.mid(spec.label.lastIndexOf(" [") + 2).chopped(1);
}

// The calculator's messages name the inputs by the labels the user sees and quote values in the
// units the inputs are typed in ("e0 = 40 µm", not "4e-05").
lubrication::SkirtInputNames LabelNames() {
  auto name = [](const std::string& key) {
    for (const InputSpec& spec : InputSpecs())
      if (spec.key == key) return NameOf(spec);
    return key;
  };
  lubrication::SkirtInputNames names{
      .e0 = name("e0"),
      .tilt = name("tilt"),
      .speed = name("speed"),
      .e0_rate = name("e0_rate"),
      .tilt_rate = name("tilt_rate"),
      .side_force = name("side_force"),
      .moment = name("moment"),
      .show = [](const std::string& input, double si) {
        for (const InputSpec& spec : InputSpecs()) {
          if (NameOf(spec) == input)
            return QString("%1 %2").arg(si / spec.scale, 0, 'g', 4).arg(UnitOf(spec)).toStdString();
        }
        return FormatValue(si);
      }};
  return names;
}

// `case_directory`: the case file's folder (files the case names relative to it).
SkirtCalculation Calculate(const engine::EngineCase& engine_case, std::string case_directory,
                           SkirtCalculatorPanel::Mode mode, std::map<std::string, double> si,
                           std::shared_ptr<std::atomic<bool>> cancel) {
  SkirtCalculation out;
  try {
    lubrication::SkirtCalculator calc(
        engine::SkirtConfigFromCase(engine_case, std::filesystem::path(case_directory)),
        LabelNames());
    calc.SetStopCheck([cancel] { return cancel->load(); });
    if (mode == SkirtCalculatorPanel::Mode::kState) {
      lubrication::SkirtState s;
      s.e0 = si["e0"];
      s.gamma = si["tilt"];
      s.e0_dot = si["e0_rate"];
      s.gamma_dot = si["tilt_rate"];
      s.piston_velocity = si["speed"];
      out.point = calc.AtState(s);
      out.ok = true;
      out.message = QString("Film at the given state (one skirt solve)");
    } else {
      const lubrication::SkirtEquilibrium eq =
          calc.AtLoad({si["side_force"], si["moment"], si["speed"]});
      out.point = eq.point;
      out.ok = eq.converged;
      out.message = eq.converged
                        ? QString("Equilibrium found: %1 iterations, %2 skirt solves")
                              .arg(eq.iterations)
                              .arg(eq.reynolds_solves)
                        : QString("No equilibrium: %1").arg(QString::fromStdString(eq.status));
    }
    const lubrication::SkirtSolver& solver = calc.solver();
    const lubrication::TriMesh& mesh = solver.mesh();
    const double radius = solver.config().geometry.radius;
    for (double x : mesh.x_lines) out.alpha_deg.push_back(x / radius * kDegreesPerRadian);
    for (double y : mesh.y_lines) out.y_mm.push_back(y * 1e3);
    const lubrication::ReynoldsSolution& fields = solver.fields();
    for (int j = 0; j < mesh.ny_nodes(); ++j) {
      for (int i = 0; i < mesh.nx_nodes(); ++i) {
        const int k = mesh.Node(i, j);
        out.pressure_mpa.push_back(fields.pressure[k] * 1e-6);
        out.contact_mpa.push_back(fields.contact_pressure[k] * 1e-6);
        out.film_um.push_back(solver.film_thickness()[k] * 1e6);
      }
    }
    const auto& g = solver.config().geometry;
    out.relief_deg.push_back({g.alpha1 * kDegreesPerRadian, 180.0 - g.alpha2 * kDegreesPerRadian});
  } catch (const InputError& e) {
    out.ok = false;
    out.message = QString::fromStdString(e.what());
  } catch (const StopRequested&) {
    out.ok = false;
    out.message = "cancelled";
  }
  return out;
}

}  // namespace

SkirtCalculatorPanel::SkirtCalculatorPanel(CaseDocument* document, QWidget* parent)
    : QWidget(parent), document_(document), cancel_(std::make_shared<std::atomic<bool>>(false)) {
  setObjectName("skirt_calculator");
  auto* layout = new QHBoxLayout(this);
  auto* left = new QWidget(this);
  auto* left_layout = new QVBoxLayout(left);
  left_layout->setContentsMargins(0, 0, 0, 0);
  auto* title = new QLabel(tr("<b>Steady skirt calculator</b> — the film of this case's skirt "
                              "at a state, or the state that carries a load (steady sliding), "
                              "without running an engine cycle"),
                           left);
  title->setWordWrap(true);
  left_layout->addWidget(title);
  auto* form = new QFormLayout;
  mode_ = new QComboBox(left);
  mode_->setObjectName("skirt_calculator_mode");
  mode_->addItem(tr("Given state: e0, tilt, rates"), int(Mode::kState));
  mode_->addItem(tr("Given load: side force and moment"), int(Mode::kLoad));
  mode_->setToolTip(
      tr("Given state: the film force and moment at that position. Given load: "
         "the position at which the film balances the load in steady sliding."));
  form->addRow(tr("Mode"), mode_);
  for (const InputSpec& spec : InputSpecs()) {
    auto* box = new QDoubleSpinBox(left);
    box->setObjectName(QString::fromStdString("skirt_calculator_" + spec.key));
    box->setRange(spec.lo, spec.hi);
    box->setDecimals(spec.decimals);
    box->setValue(spec.value);
    box->setKeyboardTracking(false);
    box->setToolTip(spec.tip);
    box->setSingleStep(std::pow(10.0, std::floor(std::log10(std::max(spec.value, 1.0)))) / 10.0);
    inputs_[spec.key] = box;
    auto* label = new QLabel(spec.label, left);
    label->setToolTip(spec.tip);
    form->addRow(label, box);
    input_rows_[spec.key] = label;
    connect(box, &QDoubleSpinBox::valueChanged, this, &SkirtCalculatorPanel::schedule);
  }
  left_layout->addLayout(form);
  status_ = new QLabel(left);
  status_->setObjectName("skirt_calculator_status");
  status_->setWordWrap(true);
  status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  left_layout->addWidget(status_);
  left_layout->addStretch(1);
  left->setMaximumWidth(380);
  layout->addWidget(left);
  table_ = new QTableWidget(0, 2, this);
  table_->setObjectName("skirt_calculator_results");
  table_->setHorizontalHeaderLabels({tr("Quantity"), tr("Value")});
  table_->verticalHeader()->hide();
  table_->verticalHeader()->setDefaultSectionSize(20);
  table_->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setMinimumWidth(200);
  layout->addWidget(table_, 2);

  auto* right = new QWidget(this);
  auto* right_layout = new QVBoxLayout(right);
  right_layout->setContentsMargins(0, 0, 0, 0);
  auto* map_row = new QHBoxLayout;
  map_row->addWidget(new QLabel(tr("Map of"), right));
  map_quantity_ = new QComboBox(right);
  map_quantity_->setObjectName("skirt_calculator_map_quantity");
  map_quantity_->addItems(
      {tr("Film pressure"), tr("Film thickness"), tr("Asperity contact pressure")});
  map_row->addWidget(map_quantity_);
  auto* caption = new QLabel(tr("— one half of the skirt, unrolled; the other half mirrors it "
                                "about the pin-axis plane"),
                             right);
  caption->setWordWrap(true);
  caption->setMinimumWidth(60);
  map_row->addWidget(caption, 1);
  right_layout->addLayout(map_row);
  map_ = new FilmMapWidget(right);
  right_layout->addWidget(map_, 1);
  layout->addWidget(right, 3);
  connect(map_quantity_, &QComboBox::currentIndexChanged, this, &SkirtCalculatorPanel::showMap);

  debounce_ = new QTimer(this);
  debounce_->setSingleShot(true);
  debounce_->setInterval(150);
  connect(debounce_, &QTimer::timeout, this, &SkirtCalculatorPanel::start);
  connect(&watcher_, &QFutureWatcher<SkirtCalculation>::finished, this,
          &SkirtCalculatorPanel::finished);
  connect(mode_, &QComboBox::currentIndexChanged, this, [this] {
    updateModeInputs();
    schedule();
  });
  connect(document_, &CaseDocument::caseChanged, this, &SkirtCalculatorPanel::schedule);
  updateModeInputs();
  schedule();
}

SkirtCalculatorPanel::~SkirtCalculatorPanel() {
  cancel_->store(true);
  watcher_.waitForFinished();  // stops at the next film solve
}

bool SkirtCalculatorPanel::busy() const { return debounce_->isActive() || running_ || pending_; }

void SkirtCalculatorPanel::updateModeInputs() {
  const bool state = Mode(mode_->currentData().toInt()) == Mode::kState;
  for (const char* key : {"e0", "tilt", "e0_rate", "tilt_rate"}) {
    inputs_.at(key)->setEnabled(state);
    input_rows_.at(key)->setEnabled(state);
  }
  for (const char* key : {"side_force", "moment"}) {
    inputs_.at(key)->setEnabled(!state);
    input_rows_.at(key)->setEnabled(!state);
  }
}

// The results shown belong to the inputs before: greyed until new ones replace them (they stay
// greyed when the new inputs give no result).
void SkirtCalculatorPanel::showResultsCurrent(bool current) {
  table_->setEnabled(current);
  map_->setEnabled(current);
}

void SkirtCalculatorPanel::schedule() {
  showResultsCurrent(false);
  debounce_->start();
}

void SkirtCalculatorPanel::start() {
  if (watcher_.isRunning()) {  // the running one is outdated: stop it, start again after
    cancel_->store(true);
    pending_ = true;
    return;
  }
  pending_ = false;
  running_ = true;
  cancel_ = std::make_shared<std::atomic<bool>>(false);
  std::map<std::string, double> si;
  for (const InputSpec& spec : InputSpecs())
    si[spec.key] = inputs_.at(spec.key)->value() * spec.scale;
  status_->setText(tr("Computing…"));
  showResultsCurrent(false);  // as schedule() does (start() also runs without it)
  watcher_.setFuture(QtConcurrent::run(Calculate, document_->engineCase(),
                                       document_->caseDirectory(),
                                       Mode(mode_->currentData().toInt()), si, cancel_));
}

void SkirtCalculatorPanel::finished() {
  running_ = false;
  if (pending_) {
    start();
    return;
  }
  SkirtCalculation result = watcher_.result();
  const bool has_point = !result.y_mm.empty();
  if (result.ok) {
    status_->setStyleSheet({});
  } else {
    status_->setStyleSheet("color: #b00020;");
  }
  status_->setText(result.message);
  if (has_point) {
    const auto& quantities = io::SkirtQuantities();
    table_->setRowCount(static_cast<int>(quantities.size()));
    for (int r = 0; r < static_cast<int>(quantities.size()); ++r) {
      const io::SkirtQuantity& q = quantities[r];
      // Parts ("  of which ...") indented under their whole, the wholes capitalised.
      const bool part = q.description.starts_with("  ");
      const QString words = QString::fromStdString(q.description).trimmed();
      auto* name =
          new QTableWidgetItem(QString("%1%2 [%3]")
                                   .arg(part ? "      " : "")
                                   .arg(part ? words : words.left(1).toUpper() + words.mid(1))
                                   .arg(QString::fromStdString(q.display_unit)));
      auto* value =
          new QTableWidgetItem(QString::number(q.value(result.point) * q.display_scale, 'g', 5));
      value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
      value->setData(Qt::UserRole, q.value(result.point));  // SI, for copying and tests
      name->setData(Qt::UserRole, QString::fromStdString(q.key));
      table_->setItem(r, 0, name);
      table_->setItem(r, 1, value);
    }
    last_ = std::move(result);
    showMap();
    showResultsCurrent(true);
  } else {
    last_ = std::move(result);
  }
  emit updated();
}

void SkirtCalculatorPanel::showMap() {
  if (!last_ || last_->y_mm.empty()) return;
  FilmMapData d;
  d.x = last_->alpha_deg;
  d.y = last_->y_mm;
  SetSkirtMapLabels(&d);
  d.no_film_x = last_->relief_deg;
  switch (map_quantity_->currentIndex()) {
    case 1:
      d.values = last_->film_um;
      d.value_title = tr("Film thickness [µm]");
      break;
    case 2:
      d.values = last_->contact_mpa;
      d.value_title = tr("Asperity contact pressure [MPa]");
      break;
    default:
      d.values = last_->pressure_mpa;
      d.value_title = tr("Film pressure [MPa]");
  }
  map_->setData(std::move(d));
}

}  // namespace filmdyn::ui
