// core's VTU/PVD writer, read back with VTK's real XML readers: geometry, cells and every point
// array survive; bad input is refused with a message naming the problem.
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <QFile>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>
#include <cmath>

#include "core/io/vtk_xml_writer.hpp"

namespace {

filmdyn::io::SurfaceField MakeGrid(int nx, int ny, double phase) {
  filmdyn::io::SurfaceField field;
  std::vector<double> pressure, thickness;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double a = M_PI * i / nx;
      field.points.push_back({std::cos(a), std::sin(a), 0.01 * j});
      pressure.push_back(1e6 * std::sin(a + phase) * j);
      thickness.push_back(1e-6 * (1.0 + i + 0.5 * j));
    }
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int n0 = j * (nx + 1) + i;
      field.triangles.push_back({n0, n0 + 1, n0 + nx + 2});
      field.triangles.push_back({n0, n0 + nx + 2, n0 + nx + 1});
    }
  }
  field.point_data = {{"pressure[Pa]", pressure}, {"film_thickness[m]", thickness}};
  return field;
}

}  // namespace

class TestVtkXmlRoundtrip : public QObject {
  Q_OBJECT
 private slots:
  void base64KnownVectors() {
    auto enc = [](const char* text) {
      return filmdyn::io::Base64Encode(reinterpret_cast<const unsigned char*>(text),
                                       std::strlen(text));
    };
    // RFC 4648 §10 test vectors.
    QCOMPARE(enc(""), std::string(""));
    QCOMPARE(enc("f"), std::string("Zg=="));
    QCOMPARE(enc("fo"), std::string("Zm8="));
    QCOMPARE(enc("foo"), std::string("Zm9v"));
    QCOMPARE(enc("foob"), std::string("Zm9vYg=="));
    QCOMPARE(enc("fooba"), std::string("Zm9vYmE="));
    QCOMPARE(enc("foobar"), std::string("Zm9vYmFy"));
  }

  void vtkReadsWhatWeWrite() {
    QTemporaryDir dir;
    const auto field = MakeGrid(12, 5, 0.3);
    const QString path = dir.filePath("skirt_0000.vtu");
    filmdyn::io::WriteVtu(path.toStdString(), field);

    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.toUtf8().constData());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    QCOMPARE(grid->GetNumberOfPoints(), vtkIdType(field.points.size()));
    QCOMPARE(grid->GetNumberOfCells(), vtkIdType(field.triangles.size()));
    QCOMPARE(grid->GetCellType(7), int(5));  // VTK_TRIANGLE
    double p[3];
    grid->GetPoint(17, p);
    for (int k = 0; k < 3; ++k) QCOMPARE(p[k], field.points[17][k]);  // Float64: exact
    vtkIdType npts;
    const vtkIdType* ids;
    grid->GetCellPoints(9, npts, ids);
    QCOMPARE(npts, vtkIdType(3));
    for (int k = 0; k < 3; ++k) QCOMPARE(int(ids[k]), field.triangles[9][k]);
    for (const auto& [name, values] : field.point_data) {
      vtkDataArray* array = grid->GetPointData()->GetArray(name.c_str());
      QVERIFY2(array != nullptr, name.c_str());
      for (std::size_t i = 0; i < values.size(); ++i) {
        // Float32 storage: relative 1e-7 of the array's scale.
        const double scale = std::max(1e-30, std::abs(values[i]));
        QVERIFY(std::abs(array->GetTuple1(vtkIdType(i)) - values[i]) <= 2e-7 * scale);
      }
    }
  }

  void pvdIndexesStepsInOrder() {
    QTemporaryDir dir;
    filmdyn::io::PvdCollection collection;
    for (int step = 0; step < 3; ++step) {
      const std::string name = "bearing_" + std::to_string(step) + ".vtu";
      filmdyn::io::WriteVtu(dir.filePath(QString::fromStdString(name)).toStdString(),
                            MakeGrid(4, 2, step));
      collection.Add(step * 1e-4, name);
    }
    const QString pvd = dir.filePath("bearing.pvd");
    collection.Write(pvd.toStdString());
    QFile file(pvd);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QXmlStreamReader xml(&file);
    QStringList files;
    QList<double> times;
    while (!xml.atEnd()) {
      xml.readNext();
      if (xml.isStartElement() && xml.name() == QLatin1String("DataSet")) {
        files << xml.attributes().value("file").toString();
        times << xml.attributes().value("timestep").toDouble();
      }
    }
    QVERIFY(!xml.hasError());
    QCOMPARE(files, QStringList({"bearing_0.vtu", "bearing_1.vtu", "bearing_2.vtu"}));
    QCOMPARE(times.last(), 2e-4);
    for (const QString& f : files) QVERIFY(QFile::exists(dir.filePath(f)));
  }

  void badInputIsRefusedAndNamed() {
    QTemporaryDir dir;
    auto field = MakeGrid(3, 2, 0.0);
    field.point_data[1].second.pop_back();
    try {
      filmdyn::io::WriteVtu(dir.filePath("x.vtu").toStdString(), field);
      QFAIL("no error for a short array");
    } catch (const std::invalid_argument& error) {
      QVERIFY(QString(error.what()).contains("film_thickness[m]"));
    }
    field = MakeGrid(3, 2, 0.0);
    field.triangles[0][2] = 999;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             filmdyn::io::WriteVtu(dir.filePath("y.vtu").toStdString(), field));
    try {
      filmdyn::io::WriteVtu("/nonexistent-dir/z.vtu", MakeGrid(2, 2, 0.0));
      QFAIL("no error for an unwritable path");
    } catch (const std::runtime_error& error) {
      QVERIFY(QString(error.what()).contains("/nonexistent-dir/z.vtu"));
    }
  }
};

QTEST_MAIN(TestVtkXmlRoundtrip)
#include "test_vtk_xml_roundtrip.moc"
