// Patir–Cheng flow/shear-stress factors and the Wu–Zheng contact factor: values of the published
// fits, continuity at every branch point, smooth-surface limits, interpolation in ln(gamma).
// Expected numbers were evaluated independently (by hand / a separate script) from the published
// formulas and coefficients cited in core/lubrication/surface/patir_cheng.cpp.
#include <QtTest>

#include <cmath>
#include <functional>

#include "core/lubrication/surface/patir_cheng.hpp"

namespace pc = filmdyn::lubrication::patir_cheng;

namespace {

constexpr double kDelta = 1e-9;      // half-width of the branch-point probes
constexpr double kJumpBound = 1e-6;  // |f(b+delta) - f(b-delta)| allowed at a branch point
constexpr double kSweepStep = 1e-5;  // H step of the [0, 20] sweep
constexpr double kSweepJump = 2e-4;  // largest |f(H+step) - f(H)| allowed (max slope ~8 => 8e-5)

double JumpAt(const std::function<double(double)>& f, double b) {
  return std::abs(f(b + kDelta) - f(b - kDelta));
}

double LargestSweepStep(const std::function<double(double)>& f) {
  double largest = 0.0;
  double previous = f(0.0);
  for (int i = 1; i <= static_cast<int>(20.0 / kSweepStep); ++i) {
    const double current = f(i * kSweepStep);
    largest = std::max(largest, std::abs(current - previous));
    previous = current;
  }
  return largest;
}

bool Near(double actual, double expected, double rel_tol) {
  return std::abs(actual - expected) <= rel_tol * std::abs(expected);
}

}  // namespace

class TestPatirCheng : public QObject {
  Q_OBJECT
 private slots:
  // [PC78] Table 1: phi_x = 1 - 0.9 exp(-0.56 H) (gamma = 1) at H = 1, 2, 3, 6
  // (0.4859, 0.7063, 0.8323, 0.9687); other gammas at one point each. Tolerance 1e-9 relative.
  void pressureFlowMatchesPublishedFit() {
    const int g1 = 3;
    QVERIFY(Near(pc::PressureFlowTabulated(g1, 1.0), 0.485912, 1e-6));
    QVERIFY(Near(pc::PressureFlowTabulated(g1, 2.0), 0.706348, 1e-6));
    QVERIFY(Near(pc::PressureFlowTabulated(g1, 3.0), 0.832263, 1e-6));
    QVERIFY(Near(pc::PressureFlowTabulated(g1, 6.0), 0.968738, 1e-6));
    QVERIFY(Near(pc::PressureFlowTabulated(0, 2.0), 0.361068425324962, 1e-9));   // 1/9
    QVERIFY(Near(pc::PressureFlowTabulated(2, 1.5), 0.3715416748118614, 1e-9));  // 1/3
    QVERIFY(Near(pc::PressureFlowTabulated(4, 1.0), 1.225, 1e-9));               // 3
    QVERIFY(Near(pc::PressureFlowTabulated(5, 4.0), 1.065, 1e-9));               // 6
    QVERIFY(Near(pc::PressureFlowTabulated(6, 2.0), 1.3075914498161483, 1e-9));  // 9
  }

  // Cross-check of the C and r columns against an independent ln(gamma) regression of the same
  // table (C = 0.89679 - 0.26591 ln g, r = 0.43006 - 0.10828 g + 0.23821 g^2 for g < 1;
  // C = -0.10667 + 0.1075 g for g > 1; R. Boman, EHD code, github.com/rboman/progs). A typo in
  // a digit of our table breaks this; the regression itself is only ~5 % accurate.
  void pressureFlowCoefficientsAgreeWithIndependentRegression() {
    for (int i = 0; i < pc::kNumGammas; ++i) {
      const double g = pc::kGammas[i];
      const double H = 2.0;
      double c = 0.0, r = 0.0, expected = 0.0;
      if (g < 1.0) {
        c = 0.89679 - 0.26591 * std::log(g);
        r = 0.43006 - 0.10828 * g + 0.23821 * g * g;
        expected = 1.0 - c * std::exp(-r * H);
      } else if (g > 1.0) {
        expected = 1.0 + (-0.10667 + 0.1075 * g) * std::pow(H, -1.5);
      } else {
        continue;  // gamma = 1 checked exactly above
      }
      QVERIFY2(std::abs(pc::PressureFlowTabulated(i, H) - expected) < 0.02,
               qPrintable(QString("gamma index %1").arg(i)));
    }
  }

  // Continuity of every curve at its lower limit (held constant below) and in a sweep.
  void pressureFlowContinuous() {
    for (int i = 0; i < pc::kNumGammas; ++i) {
      auto f = [i](double H) { return pc::PressureFlowTabulated(i, H); };
      QVERIFY(JumpAt(f, pc::PressureFlowLowerLimit(i)) < kJumpBound);
      QVERIFY(LargestSweepStep(f) < kSweepJump);
      QVERIFY(f(0.0) > 0.0);  // positive everywhere, also below the fit's range
      QCOMPARE(f(0.0), f(pc::PressureFlowLowerLimit(i)));
    }
  }

  // [PC79] shear flow factor, gamma = 1 at H = 1, 2, 3 and gamma = 9 at H = 2 (1e-9 relative);
  // the H > 5 branch uses A2 = 1.126 within 0.1 %.
  void shearFlowMatchesPublishedFit() {
    QVERIFY(Near(pc::ShearFlowTabulated(3, 1.0), 0.7955889920212664, 1e-9));
    QVERIFY(Near(pc::ShearFlowTabulated(3, 2.0), 0.7265933356364209, 1e-9));
    QVERIFY(Near(pc::ShearFlowTabulated(3, 3.0), 0.5532017447493206, 1e-9));
    QVERIFY(Near(pc::ShearFlowTabulated(6, 2.0), 0.23817237983456477, 1e-9));
    QVERIFY(Near(pc::ShearFlowTabulated(3, 8.0), 0.1523875289244259, 1e-3));
  }

  // The published A2 of every curve equals the continuity value at H = 5 within 0.1 %: this
  // checks A1, alpha1..3 and A2 of each row against each other (any mistyped digit fails).
  void shearFlowTailAmplitudeConsistentWithTable() {
    for (int i = 0; i < pc::kNumGammas; ++i) {
      QVERIFY2(Near(pc::ShearFlowTailAmplitude(i), pc::ShearFlowPublishedTailAmplitude(i), 1e-3),
               qPrintable(QString("gamma index %1: %2 vs %3")
                              .arg(i)
                              .arg(pc::ShearFlowTailAmplitude(i))
                              .arg(pc::ShearFlowPublishedTailAmplitude(i))));
    }
  }

  void shearFlowContinuous() {
    for (int i = 0; i < pc::kNumGammas; ++i) {
      auto f = [i](double H) { return pc::ShearFlowTabulated(i, H); };
      QVERIFY(JumpAt(f, 0.5) < kJumpBound);
      // 1e-8 (slope * 2e-9 is ~3e-10); the published A2 would leave jumps of 2e-6..4e-5.
      QVERIFY2(JumpAt(f, 5.0) < 1e-8, qPrintable(QString::number(JumpAt(f, 5.0))));
      QVERIFY(LargestSweepStep(f) < kSweepJump);
    }
  }

  // [PC79] Phi_fs (gamma = 1: 1.1468, 0.7321, 0.2996 at H = 1, 2, 3; gamma = 1/9 at H = 2) and
  // Phi_fp (gamma = 1: 0.2764, 0.6260, 0.8067; gamma = 9 at H = 2), 1e-9 relative.
  void shearStressFactorsMatchPublishedFits() {
    QVERIFY(Near(pc::ShearStressFsTabulated(3, 1.0), 1.1467651989224121, 1e-9));
    QVERIFY(Near(pc::ShearStressFsTabulated(3, 2.0), 0.7320657807921556, 1e-9));
    QVERIFY(Near(pc::ShearStressFsTabulated(3, 3.0), 0.29961393845943957, 1e-9));
    QVERIFY(Near(pc::ShearStressFsTabulated(0, 2.0), 1.1553292748054464, 1e-9));
    QVERIFY(Near(pc::ShearStressFpTabulated(3, 1.0), 0.27640813171162115, 1e-9));
    QVERIFY(Near(pc::ShearStressFpTabulated(3, 2.0), 0.6260105772478095, 1e-9));
    QVERIFY(Near(pc::ShearStressFpTabulated(3, 3.0), 0.8067030677647501, 1e-9));
    QVERIFY(Near(pc::ShearStressFpTabulated(6, 2.0), 0.8817212018182671, 1e-9));
  }

  // Every row of every table at H = 2, evaluated independently from the printed coefficients
  // (1e-12 relative): a mistyped digit in any row fails here.
  void everyTableRowAtH2() {
    const double phi_x[] = {0.361068425324962, 0.40423947766787, 0.490581582353686,
                            0.706348184839265, 1.07954951288349, 1.1838477631085,
                            1.30759144981615};
    const double phi_s[] = {1.05359856532401,  1.00256660425163,  0.922728066335598,
                            0.726593335636421, 0.404081343794414, 0.308631728603733,
                            0.238172379834565};
    const double phi_fs[] = {1.15532927480545,  1.07537655494236,  0.920996282855439,
                             0.732065780792156, 0.354149386867332, 0.298829106279711,
                             0.208793294879452};
    const double phi_fp[] = {0.466283430242242, 0.487210756276142, 0.53917531410257,
                             0.62601057724781,  0.798144403759214, 0.842835021594136,
                             0.881721201818267};
    for (int i = 0; i < pc::kNumGammas; ++i) {
      QVERIFY(Near(pc::PressureFlowTabulated(i, 2.0), phi_x[i], 1e-12));
      QVERIFY(Near(pc::ShearFlowTabulated(i, 2.0), phi_s[i], 1e-12));
      QVERIFY(Near(pc::ShearStressFsTabulated(i, 2.0), phi_fs[i], 1e-12));
      QVERIFY(Near(pc::ShearStressFpTabulated(i, 2.0), phi_fp[i], 1e-12));
    }
  }

  // [PC79] closed form of Phi_f: both branches give 35/32 * 16/15 = 7/6 at H = 3; -> 1 + 1/H^2
  // for large H (series of the closed form); the large-H series joins the closed form at
  // H = 15 within 1e-10 (slope there ~6e-4, so the 2e-9 probe itself accounts for ~1e-12).
  void shearStressFClosedForm() {
    QVERIFY(Near(pc::ShearStressF(3.0), 7.0 / 6.0, 1e-14));
    QVERIFY(JumpAt(pc::ShearStressF, 3.0) < kJumpBound);
    QVERIFY(JumpAt(pc::ShearStressF, 15.0) < 1e-10);
    QVERIFY(Near(pc::ShearStressF(100.0), 1.0 + 1.0 / 1e4, 1e-6));
    QVERIFY(Near(pc::ShearStressF(1e4), 1.0 + 1e-8, 1e-12));
    QCOMPARE(pc::ShearStressF(0.0), 0.0);
    QCOMPARE(pc::ShearStressF(-1.0), 0.0);
    QVERIFY(LargestSweepStep(pc::ShearStressF) < kSweepJump);
  }

  void shearStressFactorsContinuous() {
    for (int i = 0; i < pc::kNumGammas; ++i) {
      auto fs = [i](double H) { return pc::ShearStressFsTabulated(i, H); };
      auto fp = [i](double H) { return pc::ShearStressFpTabulated(i, H); };
      for (double b : {0.5, 6.0, 7.0}) QVERIFY(JumpAt(fs, b) < kJumpBound);
      QVERIFY(JumpAt(fp, 0.5) < kJumpBound);
      QVERIFY(LargestSweepStep(fs) < kSweepJump);
      QVERIFY(LargestSweepStep(fp) < kSweepJump);
      QCOMPARE(fs(6.0), pc::ShearStressFsRawFit(i, 6.0));  // taper leaves H <= 6 untouched
    }
  }

  // [WZ89] phi_c = exp(-0.6912 + 0.782 H - 0.304 H^2 + 0.0401 H^3): 0.50097, 0.84105, 0.97785
  // at H = 0, 1, 2 (raw fit 1e-9; with the continuity correction 0.1 %); exactly 1 at H >= 3.
  void contactFactorMatchesPublishedFit() {
    QVERIFY(Near(pc::WuZhengContactFactorRawFit(0.0), 0.5009745387735354, 1e-9));
    QVERIFY(Near(pc::WuZhengContactFactorRawFit(1.0), 0.8410535052886866, 1e-9));
    QVERIFY(Near(pc::WuZhengContactFactorRawFit(2.0), 0.9778490172059748, 1e-9));
    QVERIFY(Near(pc::WuZhengContactFactor(0.0), 0.5009745387735354, 1e-12));
    QVERIFY(Near(pc::WuZhengContactFactor(1.0), 0.8410535052886866, 1e-3));
    QVERIFY(Near(pc::WuZhengContactFactor(2.0), 0.9778490172059748, 1e-3));
    QCOMPARE(pc::WuZhengContactFactor(3.0), 1.0);
    QCOMPARE(pc::WuZhengContactFactor(-0.5), pc::WuZhengContactFactor(0.0));
  }

  // The mean gap the contact factor implies, h_T = h + sigma E(H) with E(H) = integral from H
  // to 3 of (1 - phi_c): against a midpoint sum written here (20 000 cells, error ~1e-10), its
  // derivative -(1 - phi_c) by central differences, zero from H = 3 on, and a Gaussian height
  // density's own mean gap, E = phi(H) - H (1 - Phi(H)) (0.0833 at H = 1, 0.3989 at H = 0),
  // which Wu and Zheng's fit follows to within 1 % of h_T (0.7 % at H = 0, 0.2 % at H = 1).
  void meanGapExcessIsTheContactFactorsIntegral() {
    auto midpoint = [](double from) {
      const int cells = 20000;
      const double dx = (3.0 - from) / cells;
      double sum = 0.0;
      for (int i = 0; i < cells; ++i) sum += 1.0 - pc::WuZhengContactFactor(from + (i + 0.5) * dx);
      return sum * dx;
    };
    for (const double H : {0.0, 0.25, 1.0, 1.5, 2.0, 2.9}) {
      QVERIFY2(
          std::abs(pc::WuZhengMeanGapExcess(H) - midpoint(H)) < 1e-9,
          qPrintable(
              QString("H %1: %2 vs %3").arg(H).arg(pc::WuZhengMeanGapExcess(H)).arg(midpoint(H))));
      const double d = 1e-4;  // (H = 0 is a kink of phi_c: one-sided there)
      const double slope =
          H > 0.0 ? (pc::WuZhengMeanGapExcess(H + d) - pc::WuZhengMeanGapExcess(H - d)) / (2 * d)
                  : (pc::WuZhengMeanGapExcess(H + 2 * d) - pc::WuZhengMeanGapExcess(H)) / (2 * d) -
                        d * 0.782 * pc::WuZhengContactFactor(0.0);  // less the curvature's part
      QVERIFY2(std::abs(slope + 1.0 - pc::WuZhengContactFactor(H)) < 1e-6,
               qPrintable(QString("H %1: slope %2").arg(H).arg(slope)));
      const double gauss_excess =
          std::exp(-0.5 * H * H) / std::sqrt(2.0 * M_PI) - H * 0.5 * std::erfc(H / std::sqrt(2.0));
      QVERIFY(std::abs(pc::WuZhengMeanGapExcess(H) - gauss_excess) < 1e-2 * (H + gauss_excess));
    }
    QCOMPARE(pc::WuZhengMeanGapExcess(3.0), 0.0);
    QCOMPARE(pc::WuZhengMeanGapExcess(7.0), 0.0);
    // Below H = 0, phi_c is held at phi_c(0): the mean gap keeps that slope.
    QVERIFY(std::abs(pc::WuZhengMeanGapExcess(-0.5) - pc::WuZhengMeanGapExcess(0.0) -
                     0.5 * (1.0 - pc::WuZhengContactFactor(0.0))) < 1e-14);
  }

  // The raw fit overshoots (exp(0.0015) at H = 3), the corrected one is continuous, monotone and
  // never above 1. The raw-fit check also proves the jump detector can fail.
  void contactFactorContinuousAndMonotone() {
    QVERIFY(JumpAt(pc::WuZhengContactFactor, 3.0) < kJumpBound);
    QVERIFY(JumpAt(pc::WuZhengContactFactor, 0.0) < kJumpBound);
    auto raw_then_one = [](double H) { return H < 3.0 ? pc::WuZhengContactFactorRawFit(H) : 1.0; };
    QVERIFY(JumpAt(raw_then_one, 3.0) > 1e-3);  // detector sees the published jump
    double previous = pc::WuZhengContactFactor(0.0);
    for (double H = 0.001; H < 4.0; H += 0.001) {
      const double current = pc::WuZhengContactFactor(H);
      QVERIFY(current >= previous);
      QVERIFY(current <= 1.0);
      previous = current;
    }
  }

  // The untapered Phi_fs cut at H = 7 jumps by ~0.013 (gamma = 1): the detector must see it.
  void rawShearStressFsCutWouldBeDiscontinuous() {
    auto cut = [](double H) { return H < 7.0 ? pc::ShearStressFsRawFit(3, H) : 0.0; };
    QVERIFY(JumpAt(cut, 7.0) > 1e-2);
  }

  // Smooth-surface limits: phi_x -> 1, Phi_s -> 0, Phi_fs = 0, Phi_fp -> 1 (1e-6 at H = 1e4).
  void smoothSurfaceLimits() {
    for (int i = 0; i < pc::kNumGammas; ++i) {
      QVERIFY(std::abs(pc::PressureFlowTabulated(i, 1e4) - 1.0) < 1e-6);
      QVERIFY(std::abs(pc::ShearFlowTabulated(i, 1e4)) < 1e-6);
      QCOMPARE(pc::ShearStressFsTabulated(i, 1e4), 0.0);
      QVERIFY(std::abs(pc::ShearStressFpTabulated(i, 1e4) - 1.0) < 1e-6);
    }
    QVERIFY(std::abs(pc::ShearStressF(1e4) - 1.0) < 1e-6);
    QCOMPARE(pc::WuZhengContactFactor(1e4), 1.0);
  }

  // Interpolation linear in ln(gamma): at gamma = sqrt(3) (midway between 1 and 3) and H = 2 the
  // factor is the mean of the two curves (0.892949); tabulated gammas reproduce the table; the
  // factor is continuous in gamma across every tabulated value (1e-8 for a 1e-9 change).
  void interpolationInLogGamma() {
    const auto mid = pc::BracketPeklenik(std::sqrt(3.0));
    QCOMPARE(mid.lo, 3);
    QCOMPARE(mid.hi, 4);
    QVERIFY(std::abs(mid.weight - 0.5) < 1e-12);
    QVERIFY(Near(pc::PressureFlow(mid, 2.0), 0.8929488488613756, 1e-9));
    for (int i = 0; i < pc::kNumGammas; ++i) {
      const double g = pc::kGammas[i];
      QCOMPARE(pc::PressureFlow(pc::BracketPeklenik(g), 1.7), pc::PressureFlowTabulated(i, 1.7));
      for (double H : {0.2, 0.8, 2.0, 5.5}) {
        const auto below = pc::BracketPeklenik(g * (1.0 - 1e-9));
        const auto above = pc::BracketPeklenik(g * (1.0 + 1e-9));
        QVERIFY(std::abs(pc::PressureFlow(below, H) - pc::PressureFlow(above, H)) < 1e-8);
        QVERIFY(std::abs(pc::ShearFlow(below, H) - pc::ShearFlow(above, H)) < 1e-8);
        QVERIFY(std::abs(pc::ShearStressFs(below, H) - pc::ShearStressFs(above, H)) < 1e-8);
        QVERIFY(std::abs(pc::ShearStressFp(below, H) - pc::ShearStressFp(above, H)) < 1e-8);
      }
    }
  }
};

QTEST_GUILESS_MAIN(TestPatirCheng)
#include "test_patir_cheng.moc"
