// How outputs are written and inputs read under faults: a full disk (/dev/full) is an error
// naming the file and the reason, an atomic write never leaves a cut or temporary file, a
// folder holding an earlier run is refused or cleaned of FilmDyn's files only, a second writer
// is locked out; input files must be regular and bounded, text must be UTF-8, echoed values
// are cut, case names become safe folder names.
#include <QTemporaryDir>
#include <QtTest>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/base/input_error.hpp"
#include "core/base/input_file.hpp"
#include "core/io/output_files.hpp"
#include "core/io/results_writer.hpp"

using namespace filmdyn;
namespace fs = std::filesystem;

namespace {
void Touch(const fs::path& file, const std::string& text = "x") {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}
std::string Slurp(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

class TestOutputFiles : public QObject {
  Q_OBJECT
 private slots:
  void fullDiskIsAnErrorNamingTheFileAndTheReason() {
    try {
      io::WriteAndSync("/dev/full", "results.csv", std::string(1 << 16, 'x'));
      QFAIL("writing to a full device did not fail");
    } catch (const io::OutputError& error) {
      const QString message = error.what();
      QVERIFY2(message.contains("results.csv"), qPrintable(message));
      QVERIFY2(message.contains("No space left on device"), qPrintable(message));
    }
  }

  void atomicWriteReplacesWholeOrNotAtAll() {
    QTemporaryDir dir;
    const fs::path target = fs::path(dir.path().toStdString()) / "summary.json";
    io::WriteFileAtomically(target, "old\n");
    io::WriteFileAtomically(target, "new\n");
    QCOMPARE(Slurp(target), std::string("new\n"));
    QVERIFY(!fs::exists(io::TemporaryFor(target)));
    // A folder that is not there: an error naming the file, nothing left behind.
    const fs::path missing = fs::path(dir.path().toStdString()) / "gone" / "results.csv";
    QVERIFY_THROWS_EXCEPTION(io::OutputError, io::WriteFileAtomically(missing, "x"));
    QVERIFY(!fs::exists(io::TemporaryFor(missing)));
  }

  void earlierRunIsRefusedOrReplacedKeepingOtherFiles() {
    QTemporaryDir dir;
    const fs::path folder = fs::path(dir.path().toStdString()) / "run";
    { const io::OutputFolder fresh(folder, io::OutputFolder::Reuse::kRefuse, "--out"); }
    Touch(folder / "results.csv");
    Touch(folder / "summary.json");
    Touch(folder / "fields" / "bearing.h5");
    Touch(folder / "fields" / "bearing.xdmf");
    Touch(folder / "plots" / "moft.png");
    Touch(folder / "plots" / "my-notes.txt");  // the user's: stays
    Touch(folder / "report.docx");             // the user's: stays
    try {
      const io::OutputFolder refused(folder, io::OutputFolder::Reuse::kRefuse, "--out");
      QFAIL("an earlier run was not refused");
    } catch (const InputError& error) {
      QCOMPARE(QString::fromStdString(error.field()), QString("--out"));
      QVERIFY(QString(error.what()).contains("--overwrite"));
    }
    QVERIFY(fs::exists(folder / "results.csv"));  // refused: nothing removed
    const io::OutputFolder replaced(folder, io::OutputFolder::Reuse::kReplace, "--out");
    QVERIFY(replaced.replaced_earlier_run());
    for (const char* gone : {"results.csv", "summary.json", "fields", "plots/moft.png"}) {
      QVERIFY2(!fs::exists(folder / gone), gone);
    }
    QVERIFY(fs::exists(folder / "plots" / "my-notes.txt"));
    QVERIFY(fs::exists(folder / "report.docx"));
  }

  void aSecondWriterIsLockedOut() {
    QTemporaryDir dir;
    const fs::path folder = fs::path(dir.path().toStdString()) / "run";
    {
      const io::OutputFolder first(folder, io::OutputFolder::Reuse::kReplace, "--out");
      // flock locks belong to the open file description: a second open in this process
      // contends like another process would.
      try {
        const io::OutputFolder second(folder, io::OutputFolder::Reuse::kReplace, "--out");
        QFAIL("a second writer was not locked out");
      } catch (const InputError& error) {
        QVERIFY(QString(error.what()).contains("another FilmDyn run"));
      }
    }
    const io::OutputFolder after(folder, io::OutputFolder::Reuse::kReplace, "--out");  // released
  }

  void inputFilesMustBeRegularAndBounded() {
    auto expect = [](const fs::path& path, std::uintmax_t limit, const char* says) {
      try {
        ReadInputFile(path, "--pressure-curve", limit);
        QFAIL(qPrintable("accepted " + QString::fromStdString(path.string())));
      } catch (const InputError& error) {
        QCOMPARE(QString::fromStdString(error.field()), QString("--pressure-curve"));
        QVERIFY2(QString(error.what()).contains(says), error.what());
      }
    };
    expect("/dev/zero", 1 << 20, "not a regular file");
    QTemporaryDir dir;
    const fs::path root(dir.path().toStdString());
    expect(root, 1 << 20, "not a regular file");
    const fs::path fifo = root / "pipe";
    QCOMPARE(::mkfifo(fifo.c_str(), 0600), 0);
    expect(fifo, 1 << 20, "not a regular file");
    expect(root / "nothing.csv", 1 << 20, "does not exist");
    Touch(root / "big.csv", std::string(5000, 'a'));
    expect(root / "big.csv", 4096, "too large (5000 bytes; at most 4096)");
    QCOMPARE(ReadInputFile(root / "big.csv", "--pressure-curve", 5000).size(), 5000u);
  }

  void textMustBeUtf8AndEchoesAreCut() {
    QVERIFY(IsUtf8("plain ascii"));
    QVERIFY(IsUtf8("Zhao–Shen µm ε"));
    QVERIFY(!IsUtf8("ab\xff"));
    QVERIFY(!IsUtf8("\xc0\xaf"));          // overlong '/'
    QVERIFY(!IsUtf8("\xed\xa0\x80"));      // a surrogate
    QVERIFY(!IsUtf8("\xf4\x90\x80\x80"));  // beyond U+10FFFF
    QVERIFY(!IsUtf8("\xe2\x82"));          // cut short
    QVERIFY_THROWS_EXCEPTION(InputError, RequireUtf8("name", "ab\xff"));
    const InputError huge("pressure[Pa]", std::string(30 << 20, '7') + "\x01", "must be a number");
    QVERIFY(std::string(huge.what()).size() < 400);
    QVERIFY(QString(huge.what()).contains(QString::number(30 << 20 | 1) + " bytes"));
    const InputError control("name", "a\nb\x1b[31m", "x");
    QCOMPARE(std::string(control.what()), std::string("name = a?b?[31m: x"));
  }

  void caseNamesBecomeSafeFolderNames() {
    QCOMPARE(io::SafeFolderName("zhao-shen-gasoline"), std::string("zhao-shen-gasoline"));
    QCOMPARE(io::SafeFolderName("../../etc"), std::string("___.._etc"));
    QCOMPARE(io::SafeFolderName("/abs/path"), std::string("_abs_path"));
    QCOMPARE(io::SafeFolderName(".hidden"), std::string("_hidden"));
    QCOMPARE(io::SafeFolderName("a\nb"), std::string("a_b"));
    QCOMPARE(io::SafeFolderName("ab\xff"), std::string("ab_"));
    QCOMPARE(io::SafeFolderName(""), std::string("case"));
    QCOMPARE(io::SafeFolderName("Kolben µ"), std::string("Kolben µ"));
    // A long name is cut to 120 bytes, never inside a character (a 300-character name made the
    // default folder's name too long for the file system).
    QCOMPARE(io::SafeFolderName(std::string(300, 'a')), std::string(120, 'a'));
    const std::string cut = io::SafeFolderName(std::string(119, 'a') + "µµ");
    QCOMPARE(cut, std::string(119, 'a'));
    QVERIFY(filmdyn::IsUtf8(
        io::SafeFolderName(std::string(60, 'b') + std::string(40, 'x') + "€€€€€€€€€€€€€€€€€€€€")));
    for (const char* name : {"..", ".", "a/../../b", "\\..\\x"}) {
      const fs::path folder = fs::path("results") / io::SafeFolderName(name);
      QCOMPARE(folder.lexically_normal().begin()->string(), std::string("results"));
      QVERIFY(std::distance(folder.begin(), folder.end()) == 2);
    }
  }

  // A signed zero (a friction power of -0, from a product with a negative zero velocity) is
  // written "0": the CSV's readers see no negative power.
  void resultsWriteNoNegativeZero() {
    namespace io = filmdyn::io;
    io::OutputRow row;
    row.crank_angle_deg = 0.0;
    row.skirt_fpl = -0.0;
    row.gas_force = -1500.0;
    std::ostringstream out;
    io::WriteResultsCsv(out, {row});
    const std::string text = out.str();
    const std::string line = text.substr(text.find('\n') + 1);
    QVERIFY2(line.find("-0") == std::string::npos || line.find("-0") == line.find("-1500"),
             line.c_str());
    QVERIFY(line.find(",0,") != std::string::npos);
  }

  void resultsConvertToDisplayUnitsOrNameTheBadCell() {
    namespace io = filmdyn::io;
    // Every column has a display unit and a positive factor.
    for (const io::ResultColumn& c : io::ResultColumns()) {
      QVERIFY2(c.display_unit != nullptr && *c.display_unit != 0 && c.display_scale > 0, c.header);
    }
    const std::string si =
        "crank_angle[deg],skirt_moft[m],gas_force[N],cylinder_pressure[Pa]\n"
        "10,2.5e-05,-1500,5000000\n"
        "11,,0,100000\n";
    const std::string display = io::ResultsCsvInDisplayUnits(si);
    QCOMPARE(QString::fromStdString(display),
             QString("crank_angle[deg],skirt_moft[um],gas_force[kN],cylinder_pressure[bar]\n"
                     "10,25,-1.5,50\n"
                     "11,,0,1\n"));
    auto error_of = [](const std::string& text) {
      try {
        io::ResultsCsvInDisplayUnits(text);
      } catch (const filmdyn::InputError& e) {
        return std::string(e.what());
      }
      return std::string();
    };
    QVERIFY(error_of("crank_angle[deg],speed[rpm]\n1,2\n").find("'speed[rpm]'") !=
            std::string::npos);
    const std::string bad = error_of("crank_angle[deg],gas_force[N]\n1,abc\n");
    QVERIFY2(bad.find("row 2") != std::string::npos && bad.find("'abc'") != std::string::npos,
             bad.c_str());
    QVERIFY(error_of("").find("empty") != std::string::npos);
  }
};

QTEST_GUILESS_MAIN(TestOutputFiles)
#include "test_output_files.moc"
