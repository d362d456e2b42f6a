// What drawing a study's plots costs as the study grows: `filmdyn study collect` draws
// DIR/plots (main effects, scatter matrix, best points) from the points' figures. This program
// times ui::ExportStudyPlots on Latin-hypercube studies of 3 factors and N points (figures from
// a smooth made-up response, every point done) and prints the wall time and the size of each
// picture. Usage: bench_study_plots [N ...]   (default: 18 100 1000 10000)
#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/batch/study.hpp"
#include "core/engine/engine_case.hpp"
#include "core/io/run_comparison.hpp"
#include "ui/plots/study_charts.hpp"

using namespace filmdyn;

namespace {

std::vector<batch::StudyRow> Rows(const batch::Study& study) {
  const std::size_t figures = io::ComparisonFigures().size();
  std::vector<batch::StudyRow> rows;
  for (const batch::StudyPoint& p : batch::DesignPoints(study, engine::EngineCase{})) {
    batch::StudyRow r;
    r.point = p;
    r.state = batch::PointState::kDone;
    r.status = "completed";
    r.wall_time_s = 9.0;
    r.figures.assign(figures, std::nullopt);
    const double a = *p.numbers[0] / 2.5e-5, b = *p.numbers[1] / 0.015, c = *p.numbers[2] / 4000;
    for (std::size_t k = 0; k < figures; ++k) {
      r.figures[k] = (1.0 + 0.3 * std::sin(double(k) + a) + 0.2 * b * double(k % 3) + 0.5 * c) *
                     std::pow(10.0, -double(k % 4));
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::stoi(argv[i]));
  if (sizes.empty()) sizes = {18, 100, 1000, 10000};
  std::printf("%8s %10s  %s\n", "points", "time [s]", "pictures [MB]");
  for (int n : sizes) {
    const std::string text = R"({"name": "bench", "design": "latin-hypercube", "points": )" +
                             std::to_string(n) + R"(, "factors": [
        {"path": "skirt.cold_clearance", "range": [1.5e-5, 3.5e-5]},
        {"path": "lubricant.viscosity", "range": [0.01, 0.02]},
        {"path": "operating.rpm", "range": [2000, 6000]}]})";
    const batch::Study study = batch::ParseStudy(text, "bench.json");
    const std::vector<batch::StudyRow> rows = Rows(study);
    QTemporaryDir dir;
    QElapsedTimer clock;
    clock.start();
    QString error;
    const QStringList files = ui::ExportStudyPlots(study, rows, dir.path(), "", false, &error);
    const double seconds = double(clock.nsecsElapsed()) * 1e-9;
    if (!error.isEmpty()) {
      std::fprintf(stderr, "bench_study_plots: %s\n", qPrintable(error));
      return 1;
    }
    std::string sizes_text;
    for (const QString& f : files) {
      sizes_text += QFileInfo(f).fileName().toStdString() + " " +
                    std::to_string(double(QFileInfo(f).size()) / 1e6).substr(0, 5) + "  ";
    }
    std::printf("%8d %10.2f  %s\n", n, seconds, sizes_text.c_str());
    std::fflush(stdout);
  }
  return 0;
}
