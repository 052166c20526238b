// Face-milling process of Landers & Ulsoy (A1-A12): pressure laws against hand values, rigid forces
// against the paper's static model F_Y = 0.76 d^0.65 f^0.63, part entry and exit (A5), integrator
// convergence in the step size, and input validation.
#include <cmath>

#include "core/invalid_input.h"
#include "supervisor/face_milling_process.h"
#include "test_registry.h"

using namespace mx;

class TestFaceMillingProcess : public QObject {
  Q_OBJECT
 private slots:
  void kinematics() {
    FaceMillingProcess p(FaceMillingParameters{});
    QCOMPARE(p.spindlePeriod(), 0.04);
    QVERIFY(std::abs(p.cuttingSpeed() - 2.0 * M_PI * 0.025 * 25.0) < 1e-12);
    QVERIFY(std::abs(p.delay() - 0.01) < 1e-12);
    QVERIFY(std::abs(p.stepSize() - 5e-5) < 1e-12);  // 200 steps per tooth period
  }

  void rigidForcesMatchPaperModel() {
    // A full-width cut (part width = cutter diameter) at 10 mm/s: F_Y within 10 % of eq. 1.
    FaceMillingProcess p(FaceMillingParameters{});
    for (double d : {1.0, 2.0}) {
      const RigidRevolution r = p.rigidRevolution(d * 1e-3, 0.1e-3);
      const double model = 760.0 * std::pow(d, 0.65) * std::pow(0.1, 0.63);
      QVERIFY2(std::abs(r.fy_max_N / model - 1.0) < 0.10, qPrintable(QString::number(r.fy_max_N)));
      QVERIFY(r.power_max_W >= r.power_mean_W);
    }
    // Hand value of A1 at f = 0.1 mm, d = 2 mm, V = 235.6 m/min: P_C = 1.335 kN/mm^2, one tooth at q = 0
    // carries F_t = P_C f d = 267 N, the peak of the tangential force of a single tooth.
    const double V = 2.0 * M_PI * 0.025 * 25.0 * 60.0;
    const double Pc = 0.29 * std::pow(0.1, -0.25) * std::pow(2.0, -0.13) * std::pow(V / 1000.0, -0.72);
    QVERIFY(std::abs(Pc - 1.335) < 0.01);
  }

  void baselinePowerAboveLimit() {
    FaceMillingProcess p(FaceMillingParameters{});
    const RigidRevolution r = p.rigidRevolution(2e-3, 0.1e-3);
    QVERIFY(r.power_max_W / 745.7 > 2.0);  // static peak ~217 % of the spindle limit
  }

  void entryAndExit() {
    FaceMillingParameters par;
    par.part_start_x_m = 0.0;
    par.part_length_m = 0.06;
    FaceMillingProcess p(par);
    p.setDepth(1e-3);
    p.setFeedRate(0.036);
    p.reset(-0.03);
    p.advance(0.1);  // tool edge still 1.4 mm before the part
    QCOMPARE(p.output().teeth_in_cut, 0);
    QCOMPARE(p.output().fy_N, 0.0);
    double max_fy = 0.0;
    while (p.output().tool_x_m < 0.03) {
      p.step();
      max_fy = std::max(max_fy, std::abs(p.output().fy_N));
    }
    QVERIFY(max_fy > 100.0);
    p.advance(1.7);  // tool centre beyond part end + radius
    QVERIFY(p.output().tool_x_m > 0.085);
    QCOMPARE(p.output().teeth_in_cut, 0);
  }

  void stepConvergence() {
    // The same 2 mm (chattering) cut with 50 us and 25 us steps: F_y after 0.4 s within 2 % of its range.
    auto run = [](double step) {
      FaceMillingParameters par;
      par.part_start_x_m = -1.0;
      par.part_length_m = 2.0;
      par.step_s = step;
      FaceMillingProcess p(par);
      p.setDepth(1.5e-3);
      p.setFeedRate(0.01);
      p.reset(0.0);
      double peak = 0.0;
      p.advance(0.2);
      for (int i = 0; i < 800; ++i) {
        p.advance(2.5e-4);
        peak = std::max(peak, std::abs(p.output().fy_N));
      }
      return peak;
    };
    const double a = run(5e-5), b = run(2.5e-5);
    QVERIFY2(std::abs(a - b) / b < 0.02, qPrintable(QString("%1 vs %2").arg(a).arg(b)));
  }

  void feedHoldStopsCutting() {
    FaceMillingParameters par;
    par.part_start_x_m = -1.0;
    par.part_length_m = 2.0;
    FaceMillingProcess p(par);
    p.setDepth(1e-3);
    p.setFeedRate(0.0076);
    p.reset(0.0);
    p.advance(0.2);
    const double x = p.output().tool_x_m;
    p.setFeedRate(0.0);
    p.advance(0.2);
    QCOMPARE(p.output().tool_x_m, x);
    QVERIFY(std::abs(p.output().fy_N) < 30.0);  // only the relaxation of the static deflection is cut
  }

  void validation() {
    FaceMillingParameters par;
    par.teeth = 0;
    QVERIFY_THROWS_EXCEPTION(InvalidInput, FaceMillingProcess{par});
    par = {};
    par.tool_y.damping_ratio = 1.5;
    try {
      FaceMillingProcess p(par);
      QFAIL("no throw");
    } catch (const InvalidInput& e) {
      QVERIFY(QString(e.what()).contains("tool_y.damping_ratio"));
    }
    FaceMillingProcess p{FaceMillingParameters{}};
    QVERIFY_THROWS_EXCEPTION(InvalidInput, p.setDepth(-1.0));
    QVERIFY_THROWS_EXCEPTION(InvalidInput, p.setFeedRate(std::nan("")));
  }
};

MX_REGISTER_TEST(TestFaceMillingProcess)
#include "test_face_milling_process.moc"
