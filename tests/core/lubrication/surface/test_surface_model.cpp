// SurfacePair validation and composite properties, and the SurfaceModel evaluated as the
// Reynolds solver uses it: symmetry of the across-factor, sign of the shear terms, smooth-surface
// limits, continuity, contact pressure, and no heap allocation per call.
#include <QtTest>

#include <atomic>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>

#include "core/base/input_error.hpp"
#include "core/lubrication/surface/greenwood_tripp.hpp"
#include "core/lubrication/surface/surface_model.hpp"
#include "core/lubrication/surface_film.hpp"

// Counts heap allocations of the whole test program, to prove the per-node calls allocate none.
namespace {
std::atomic<long> g_allocations{0};
}
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace fl = filmdyn::lubrication;

namespace {

// Al-Si piston skirt on a cast-iron-like liner; composite roughness 0.5 um.
fl::SurfacePair SkirtLiner() {
  fl::SurfacePair pair;
  pair.sigma1 = 0.3e-6;
  pair.sigma2 = 0.4e-6;
  pair.E1 = 70e9;
  pair.nu1 = 0.33;
  pair.E2 = 210e9;
  pair.nu2 = 0.3;
  return pair;
}

// Returns the field named by the InputError thrown by Validate, or "" if none was thrown.
QString RejectedField(const fl::SurfacePair& pair) {
  try {
    pair.Validate("skirt.surface");
  } catch (const filmdyn::InputError& error) {
    return QString::fromStdString(error.field());
  }
  return QString();
}

}  // namespace

class TestSurfaceModel : public QObject {
  Q_OBJECT
 private slots:
  void compositeSigma() {
    QCOMPARE(SkirtLiner().CompositeSigma(), 0.5e-6);  // 3-4-5
  }

  // E' = 2 / [(1-nu1^2)/E1 + (1-nu2^2)/E2] (Hu et al. 1994): aluminium 70 GPa / 0.33 on steel
  // 210 GPa / 0.3 gives 117.21 GPa (twice the Hertz E* = 58.6 GPa); steel on steel
  // E/(1-nu^2) = 230.77 GPa. 1e-9 relative.
  void compositeModulus() {
    const double e_prime = SkirtLiner().CompositeModulus();
    QVERIFY(std::abs(e_prime / 117.2103926548e9 - 1.0) < 1e-9);
    fl::SurfacePair steel = SkirtLiner();
    steel.E1 = steel.E2 = 210e9;
    steel.nu1 = steel.nu2 = 0.3;
    QVERIFY(std::abs(steel.CompositeModulus() / (210e9 / 0.91) - 1.0) < 1e-12);
    const double hertz = 1.0 / ((1 - 0.33 * 0.33) / 70e9 + (1 - 0.09) / 210e9);
    QVERIFY(std::abs(e_prime / hertz - 2.0) < 1e-12);
  }

  void validInputAccepted() {
    QCOMPARE(RejectedField(SkirtLiner()), QString());
    fl::SurfacePair one_smooth = SkirtLiner();
    one_smooth.sigma2 = 0.0;
    QCOMPARE(RejectedField(one_smooth), QString());
    fl::SurfacePair typed = SkirtLiner();
    typed.peklenik = 0.1111;  // 1/9 as typed in a table cell
    QCOMPARE(RejectedField(typed), QString());
  }

  void badInputNamesField_data() {
    QTest::addColumn<QString>("member");
    QTest::addColumn<double>("value");
    QTest::addColumn<QString>("field");
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    QTest::newRow("negative sigma1") << "sigma1" << -1e-7 << "skirt.surface.sigma1";
    QTest::newRow("negative sigma2") << "sigma2" << -1e-7 << "skirt.surface.sigma2";
    QTest::newRow("nan sigma2") << "sigma2" << nan << "skirt.surface.sigma2";
    QTest::newRow("zero E1") << "E1" << 0.0 << "skirt.surface.E1";
    QTest::newRow("negative E2") << "E2" << -1.0 << "skirt.surface.E2";
    QTest::newRow("inf E2") << "E2" << inf << "skirt.surface.E2";
    QTest::newRow("nu1 = 0.5") << "nu1" << 0.5 << "skirt.surface.nu1";
    QTest::newRow("nu2 = -1") << "nu2" << -1.0 << "skirt.surface.nu2";
    QTest::newRow("nan nu2") << "nu2" << nan << "skirt.surface.nu2";
    QTest::newRow("peklenik 0.1") << "peklenik" << 0.1 << "skirt.surface.peklenik";
    QTest::newRow("peklenik 10") << "peklenik" << 10.0 << "skirt.surface.peklenik";
    QTest::newRow("peklenik nan") << "peklenik" << nan << "skirt.surface.peklenik";
    QTest::newRow("gt_k 0") << "gt_k" << 0.0 << "skirt.surface.gt_k";
    QTest::newRow("mu_f < 0") << "boundary_friction" << -0.1 << "skirt.surface.boundary_friction";
  }

  void badInputNamesField() {
    QFETCH(QString, member);
    QFETCH(double, value);
    QFETCH(QString, field);
    fl::SurfacePair pair = SkirtLiner();
    if (member == "sigma1") pair.sigma1 = value;
    if (member == "sigma2") pair.sigma2 = value;
    if (member == "E1") pair.E1 = value;
    if (member == "E2") pair.E2 = value;
    if (member == "nu1") pair.nu1 = value;
    if (member == "nu2") pair.nu2 = value;
    if (member == "peklenik") pair.peklenik = value;
    if (member == "gt_k") pair.gt_k = value;
    if (member == "boundary_friction") pair.boundary_friction = value;
    QCOMPARE(RejectedField(pair), field);
  }

  void bothSurfacesSmoothRejected() {
    fl::SurfacePair pair = SkirtLiner();
    pair.sigma1 = pair.sigma2 = 0.0;
    QCOMPARE(RejectedField(pair), QString("skirt.surface.sigma1"));
    QVERIFY_THROWS_EXCEPTION(filmdyn::InputError, fl::SurfaceModel{pair});
  }

  void constructorValidates() {
    fl::SurfacePair pair = SkirtLiner();
    pair.E1 = 0.0;
    QVERIFY_THROWS_EXCEPTION(filmdyn::InputError, fl::SurfaceModel{pair});
  }

  // phi_across(gamma) = phi_along(1/gamma) for tabulated and intermediate gammas (1e-12).
  void acrossIsAlongAtInverseGamma() {
    for (double gamma : {1.0 / 9.0, 0.2, 1.0 / 3.0, 0.7, 1.0, 2.0, 3.0, 4.5, 9.0}) {
      fl::SurfacePair pair = SkirtLiner();
      pair.peklenik = gamma;
      fl::SurfacePair inverse = pair;
      inverse.peklenik = 1.0 / gamma;
      const fl::SurfaceModel model(pair);
      const fl::SurfaceModel inverse_model(inverse);
      for (double H : {0.3, 0.9, 1.5, 3.0, 6.0}) {
        QVERIFY(std::abs(model.Flow(H).pressure_across - inverse_model.Flow(H).pressure_along) <
                1e-12);
      }
    }
    fl::SurfacePair iso = SkirtLiner();
    const fl::SurfaceModel isotropic(iso);
    QCOMPARE(isotropic.Flow(1.3).pressure_across, isotropic.Flow(1.3).pressure_along);
  }

  // phi_s = (Vr1 - Vr2) Phi_s: 0 for equal roughness, flips sign when the surfaces are swapped,
  // equals +Phi_s when only surface 1 is rough. Same for Phi_fs.
  void shearTermsSignConvention() {
    fl::SurfacePair pair = SkirtLiner();  // Vr1 - Vr2 = (0.09 - 0.16)/0.25 = -0.28
    fl::SurfacePair swapped = pair;
    std::swap(swapped.sigma1, swapped.sigma2);
    fl::SurfacePair equal = pair;
    equal.sigma1 = equal.sigma2 = 0.4e-6;
    fl::SurfacePair only1 = pair;
    only1.sigma2 = 0.0;
    const fl::SurfaceModel model(pair), model_swapped(swapped), model_equal(equal),
        model_only1(only1);
    const double H = 2.0;
    const double phi_s_one_rough = 0.7265933356364209;  // [PC79] gamma = 1, H = 2
    QVERIFY(std::abs(model_only1.Flow(H).shear - phi_s_one_rough) < 1e-12);
    QVERIFY(std::abs(model.Flow(H).shear - (-0.28) * phi_s_one_rough) < 1e-12);
    QCOMPARE(model_swapped.Flow(H).shear, -model.Flow(H).shear);
    QCOMPARE(model_equal.Flow(H).shear, 0.0);
    QVERIFY(model_only1.Shear(H).fs > 0.0);
    QCOMPARE(model_swapped.Shear(H).fs, -model.Shear(H).fs);
    QCOMPARE(model_equal.Shear(H).fs, 0.0);
  }

  // Smooth-surface limits at H = 1e4: phi_x, phi_y, phi_c, Phi_f, Phi_fp -> 1 and phi_s,
  // Phi_fs -> 0 (1e-6), and p_c = 0 (fit) / < 1e-300 (exact).
  void smoothSurfaceLimits() {
    for (double gamma : {1.0 / 9.0, 0.5, 1.0, 6.0, 9.0}) {
      fl::SurfacePair pair = SkirtLiner();
      pair.sigma2 = 0.0;
      pair.peklenik = gamma;
      const fl::SurfaceModel model(pair);
      const fl::FlowFactors flow = model.Flow(1e4);
      const fl::ShearStressFactors shear = model.Shear(1e4);
      QVERIFY(std::abs(flow.pressure_along - 1.0) < 1e-6);
      QVERIFY(std::abs(flow.pressure_across - 1.0) < 1e-6);
      QVERIFY(std::abs(flow.shear) < 1e-6);
      QCOMPARE(flow.contact, 1.0);
      QVERIFY(std::abs(shear.f - 1.0) < 1e-6);
      QCOMPARE(shear.fs, 0.0);
      QVERIFY(std::abs(shear.fp - 1.0) < 1e-6);
      QCOMPARE(model.ContactPressure(1e4 * model.sigma()), 0.0);
    }
  }

  // Every factor, for a non-tabulated gamma (interpolated), is continuous: probes at all branch
  // points (jump < 1e-6 over 2e-9) and a sweep of H in [0, 20] with step 1e-5 that finds no
  // step larger than 2e-4 (max slope ~8 => 8e-5 expected).
  void allFactorsContinuousInH() {
    fl::SurfacePair pair = SkirtLiner();
    pair.sigma2 = 0.0;  // Vr1 - Vr2 = 1: shear factors at full size
    pair.peklenik = 0.25;
    const fl::SurfaceModel model(pair);
    auto components = [&model](double H) {
      const fl::FlowFactors f = model.Flow(H);
      const fl::ShearStressFactors s = model.Shear(H);
      return std::array<double, 7>{
          f.pressure_along, f.pressure_across, f.shear, f.contact, s.f, s.fs, s.fp};
    };
    for (double b : {0.0, 0.5, 0.75, 1.0, 3.0, 5.0, 6.0, 7.0, 15.0}) {
      const auto lo = components(b - 1e-9);
      const auto hi = components(b + 1e-9);
      for (std::size_t k = 0; k < lo.size(); ++k) {
        QVERIFY2(std::abs(hi[k] - lo[k]) < 1e-6,
                 qPrintable(QString("branch %1, component %2").arg(b).arg(k)));
      }
    }
    auto previous = components(0.0);
    double largest = 0.0;
    for (int i = 1; i <= 2000000; ++i) {
      const auto current = components(i * 1e-5);
      for (std::size_t k = 0; k < current.size(); ++k) {
        largest = std::max(largest, std::abs(current[k] - previous[k]));
      }
      previous = current;
    }
    QVERIFY2(largest < 2e-4, qPrintable(QString::number(largest)));
  }

  // p_c = K E' F_5/2(h/sigma): at h = sigma (H = 1), fit: 1.198e-4 * 117.21 GPa * 0.0777381 =
  // 1.0916 MPa; exact: F = 0.0805623 -> 1.1313 MPa (1e-6 relative). Both continuous and
  // decreasing; the derivative matches a central difference (1e-5 relative).
  void contactPressure() {
    fl::SurfacePair pair = SkirtLiner();
    const double k_e = 1.198e-4 * pair.CompositeModulus();
    const fl::SurfaceModel fit(pair);
    pair.asperity_model = fl::AsperityModel::kGreenwoodTrippExact;
    const fl::SurfaceModel exact(pair);
    const double sigma = fit.sigma();
    QVERIFY(std::abs(fit.ContactPressure(sigma) / (k_e * 7.77380627e-2) - 1.0) < 1e-6);
    QVERIFY(std::abs(exact.ContactPressure(sigma) / (k_e * 8.05623356e-2) - 1.0) < 1e-6);
    QCOMPARE(fit.ContactPressure(4.0 * sigma), 0.0);
    QVERIFY(exact.ContactPressure(4.0 * sigma) > 0.0);
    for (const fl::SurfaceModel* model : {&fit, &exact}) {
      for (double H : {-0.5, 0.0, 0.8, 2.0, 3.5}) {
        const double h = H * sigma;
        const double dh = 1e-6 * sigma;
        const double numeric =
            (model->ContactPressure(h + dh) - model->ContactPressure(h - dh)) / (2.0 * dh);
        QVERIFY2(std::abs(model->ContactPressureDerivative(h) / numeric - 1.0) < 1e-5,
                 qPrintable(QString("H = %1").arg(H)));
        QVERIFY(model->ContactPressure(h + dh) < model->ContactPressure(h));
      }
    }
  }

  // Per-node evaluation must not touch the heap (requirement: evaluated at every FEM node).
  void tabulatedFilmMatchesTheFormulas();
  void noAllocationPerCall() {
    fl::SurfacePair pair = SkirtLiner();
    pair.peklenik = 2.0;
    pair.asperity_model = fl::AsperityModel::kGreenwoodTrippExact;
    const fl::SurfaceModel model(pair);
    double sink = 0.0;
    const long before = g_allocations.load();
    for (int i = 0; i < 10000; ++i) {
      const double H = -1.0 + 1e-3 * i;
      const fl::FlowFactors f = model.Flow(H);
      const fl::ShearStressFactors s = model.Shear(H);
      sink += f.pressure_along + f.shear + s.fs + model.ContactPressure(H * model.sigma()) +
              model.ContactPressureDerivative(H * model.sigma());
    }
    const long after = g_allocations.load();
    QVERIFY(std::isfinite(sink));
    QCOMPARE(after - before, 0L);
  }
};


// The film model the joints use reads the factors from a table: within 1e-5 of the formulas
// (each factor's scale: 1, or the asperity pressure at H = 0) over the whole table, at the
// branch points of the fits and just beside them, for the asperity fit and the exact
// Greenwood–Tripp integral, three Peklenik numbers, unequal roughness (phi_s, Phi_fs != 0);
// beyond the table and for h < 0 the formulas themselves.
void TestSurfaceModel::tabulatedFilmMatchesTheFormulas() {
  for (const double gamma : {1.0, 1.0 / 9.0, 3.7}) {
    for (const fl::AsperityModel asperity :
         {fl::AsperityModel::kGreenwoodTrippFit, fl::AsperityModel::kGreenwoodTrippExact}) {
      fl::SurfacePair pair;
      pair.sigma1 = 0.4e-6;
      pair.sigma2 = 0.3e-6;
      pair.peklenik = gamma;
      pair.E1 = 210e9;
      pair.E2 = 110e9;
      pair.asperity_model = asperity;
      const fl::TabulatedSurfaceFilm table(pair);
      const fl::SurfaceFilm& direct = table.direct();
      const double sigma = direct.sigma();
      const double pc_scale = direct.At(0.0).contact_pressure;
      QVERIFY(pc_scale > 1e6);
      std::vector<double> hs;
      for (int i = 0; i <= 400000; ++i) hs.push_back(520.0 * i / 400000.0 * 1.0000371);
      for (double kink : {0.5, 0.75, 1.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 15.0, 64.0, 512.0}) {
        for (double d : {-1e-9, 0.0, 1e-9, 3e-4}) hs.push_back(kink + d);
      }
      double worst = 0.0;
      for (const double H : hs) {
        const fl::NodalFilmFactors a = table.At(H * sigma), b = direct.At(H * sigma);
        const double e[] = {a.phi_along - b.phi_along,
                            a.phi_across - b.phi_across,
                            a.phi_shear - b.phi_shear,
                            a.phi_contact - b.phi_contact,
                            (a.contact_pressure - b.contact_pressure) / pc_scale,
                            a.shear_f - b.shear_f,
                            a.shear_fs - b.shear_fs,
                            a.shear_fp - b.shear_fp};
        for (double x : e) worst = std::max(worst, std::abs(x));
      }
      qInfo("gamma %.3f, %s: largest table error %.2e", gamma,
            asperity == fl::AsperityModel::kGreenwoodTrippFit ? "fit" : "exact", worst);
      QVERIFY2(worst < 1e-5, qPrintable(QString::number(worst)));
      // Outside the table: the formulas exactly.
      for (const double H : {-0.3, 600.0, 1e5}) {
        const fl::NodalFilmFactors a = table.At(H * sigma), b = direct.At(H * sigma);
        QCOMPARE(a.phi_along, b.phi_along);
        QCOMPARE(a.shear_f, b.shear_f);
        QCOMPARE(a.contact_pressure, b.contact_pressure);
      }
    }
  }
}

QTEST_GUILESS_MAIN(TestSurfaceModel)
#include "test_surface_model.moc"
