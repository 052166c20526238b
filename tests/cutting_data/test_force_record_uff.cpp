// Dynamometer records as universal files (dataset 58/58b, function type 1): the rigid-tool force model's
// forces written in each layout average to the CSV record's means and give the coefficients back; other
// datasets are skipped; each bad input names its line and value.
#include <cmath>
#include <numbers>

#include "core/invalid_input.h"
#include "cutting_data/coefficient_fit.h"
#include "cutting_data/force_record_uff.h"
#include "model/cutting_force.h"
#include "support/force_record_uff_samples.h"
#include "support/test_constants.h"
#include "test_registry.h"

using namespace mx;
using mx::test::ForceUffLayout;

namespace {
using mx::test::kPi;
constexpr double kRpm = 3000.0;  // a revolution of 20 ms
constexpr double kKt = 6e8, kKr = 0.3, kKa = 1.5e8;
constexpr double kSampleS = 5e-5;  // 400 samples a revolution
constexpr int kSamples = 1321;     // 3.3 revolutions

// Three teeth: their forces do not add up to a constant, so the averaging over whole revolutions counts.
TestCutSetup threeToothSlotting() {
  return {3, 16e-3, 2e-3, 1.0, MillingDirection::Down};
}

// The rigid-tool model of cutting_force.h (no edge forces) sampled at kSampleS: F_x and F_y, and
// F_z = (K_ac / K_t) sum F_t, since each tooth's axial force K_ac a h goes with its tangential K_t a h.
ForceRecord modelRecord(const TestCutSetup& t, double feed_m) {
  MillingSetup s;
  s.teeth = t.teeth;
  s.diameter_m = t.diameter_m;
  s.tangential_coefficient_pa = kKt;
  s.radial_ratio = kKr;
  s.direction = t.direction;
  s.radial_depth_m = t.radial_ratio * t.diameter_m;
  s.immersion = Immersion::fromRadialDepth(s.radial_depth_m, s.diameter_m, s.direction);
  const StaticCut cut(s, OperatingPoint{kRpm / 60.0, t.depth_m, feed_m});
  ForceRecord r;
  for (int i = 0; i < kSamples; ++i) {
    const double time = i * kSampleS;
    const StaticForce f = cut.at(2.0 * kPi * kRpm / 60.0 * time);
    r.t_s.push_back(time);
    r.fx_n.push_back(f.fx_n);
    r.fy_n.push_back(f.fy_n);
    r.fz_n.push_back(kKa / kKt * f.tangential_sum_n);
  }
  return r;
}

// Four samples of a small record for the error cases.
ForceRecord smallRecord() {
  return {{0.0, 0.001, 0.002, 0.003}, {-10.0, -12.0, -11.0, -9.0}, {100.0, 120.0, 110.0, 90.0}, {5.0, 6.0, 7.0, 8.0}};
}

double relativeError(double got, double want) {
  return std::abs(got / want - 1.0);
}

QString inputError(const std::string& bytes) {
  try {
    readForceRecordUff(bytes, "cut.unv");
  } catch (const InvalidInput& e) {
    return QString::fromUtf8(e.what());
  }
  return "accepted";
}
}  // namespace

Q_DECLARE_METATYPE(mx::test::ForceUffLayout)

class TestForceRecordUff : public QObject {
  Q_OBJECT
 private slots:
  // The same samples through the UFF reader and the CSV record reader: the same means over whole
  // revolutions. The CSV holds the samples exactly as the file stores them (digits, float, units).
  void sameMeansAsTheCsvRecord_data() {
    QTest::addColumn<ForceUffLayout>("layout");
    ForceUffLayout l;
    QTest::newRow("58, even, double, N, s") << l;
    l.even = false;
    QTest::newRow("58, uneven pairs") << l;
    l.binary = true;
    QTest::newRow("58b, uneven, double") << l;
    l.even = true;
    l.ordinate_type = 2;
    QTest::newRow("58b, even, single") << l;
    l = {};
    l.ordinate_type = 2;
    QTest::newRow("58, even, single (E13.5)") << l;
    l = {};
    l.directions = {-1, 2, -3};
    l.force_units = "kN";
    l.force_factor = 1e3;
    QTest::newRow("-x, -z, kN") << l;
    l.force_units = "lbf";
    l.force_factor = 4.4482216152605;
    l.time_units = "ms";
    l.time_factor = 1e-3;
    QTest::newRow("lbf, ms") << l;
  }
  void sameMeansAsTheCsvRecord() {
    QFETCH(ForceUffLayout, layout);
    const ForceRecord model = modelRecord(threeToothSlotting(), 0.1e-3);
    const ForceRecord uff = readForceRecordUff(mx::test::forceRecordUff(model, layout), "cut.unv");
    const ForceRecord csv =
        readForceRecordCsv(mx::test::forceRecordCsv(mx::test::storedRecord(model, layout)), "c.csv");
    QCOMPARE(uff.t_s.size(), std::size_t(kSamples));
    const TestCut a = meanOverRevolutions(uff, kRpm, 0.1e-3, "cut.unv");
    const TestCut b = meanOverRevolutions(csv, kRpm, 0.1e-3, "c.csv");
    QVERIFY2(relativeError(a.fx_n, b.fx_n) < 1e-9, qPrintable(QString("%1 %2").arg(a.fx_n, 0, 'g', 17).arg(b.fx_n)));
    QVERIFY(relativeError(a.fy_n, b.fy_n) < 1e-9);
    QVERIFY(relativeError(a.fz_n, b.fz_n) < 1e-9);
    // The slotting closed forms (Altintas eq. 2.26): the file does not move the means off the model's.
    const TestCut exact = meanCutForces(threeToothSlotting(), {kKt, kKr * kKt, kKa, 0.0, 0.0, 0.0}, 0.1e-3);
    QVERIFY2(relativeError(a.fy_n, exact.fy_n) < 1e-4, qPrintable(QString::number(relativeError(a.fy_n, exact.fy_n))));
  }

  // Five cuts, each a UFF record of the model's forces, averaged and fitted: K_t, K_r and K_ac to 0.1 %.
  void coefficientsComeBack() {
    const TestCutSetup t = threeToothSlotting();
    std::vector<TestCut> cuts;
    for (double c : {0.05e-3, 0.1e-3, 0.15e-3, 0.2e-3, 0.25e-3}) {
      const ForceRecord r = readForceRecordUff(mx::test::forceRecordUff(modelRecord(t, c)), "cut.unv");
      cuts.push_back(meanOverRevolutions(r, kRpm, c, "cut.unv"));
    }
    const CoefficientFit fit = fitCuttingCoefficients(t, cuts);
    const CuttingCoefficients& k = fit.coefficients;
    const QString got = QString("Kt %1 Kr %2 Ka %3 (relative errors)")
                            .arg(relativeError(k.Ktc_pa, kKt))
                            .arg(relativeError(fit.Kr(), kKr))
                            .arg(relativeError(k.Kac_pa, kKa));
    QVERIFY2(relativeError(k.Ktc_pa, kKt) < 1e-3, qPrintable(got));
    QVERIFY2(relativeError(fit.Kr(), kKr) < 1e-3, qPrintable(got));
    QVERIFY2(relativeError(k.Kac_pa, kKa) < 1e-3, qPrintable(got));
    // No edge forces in the model: the edge coefficients vanish next to a cut's force per unit depth.
    const double scale = kKt * 0.05e-3;
    QVERIFY(std::abs(k.Kte_n_per_m) < 1e-3 * scale && std::abs(k.Kae_n_per_m) < 1e-3 * scale);
  }

  // Datasets other than 58, FRFs and rotations are skipped; a byte order mark and blank lines lead in.
  void skipsWhatIsNotAForce() {
    const ForceRecord r = smallRecord();
    ForceUffLayout moment;
    moment.directions = {6, 2, 3};
    mx::test::Uff58Text frf;
    frf.data = {" 1.0 2.0 3.0 4.0"};
    const std::string text = "\xEF\xBB\xBF\n" + mx::test::otherDataset(151) + frf.text() +
                             mx::test::forceDataset(r.t_s, r.fz_n, 0, moment) + mx::test::forceRecordUff(r);
    QVERIFY(isUniversalFile(text));
    const ForceRecord got = readForceRecordUff(text, "cut.unv");
    QCOMPARE(got.t_s, r.t_s);
    QCOMPARE(got.fx_n, r.fx_n);
    QCOMPARE(got.fy_n, r.fy_n);
    QCOMPARE(got.fz_n, r.fz_n);
    QVERIFY(!isUniversalFile("time_s,Fx_N,Fy_N,Fz_N\n0,1,2,3\n"));
    QVERIFY(!isUniversalFile(""));
  }

  // Each bad input: the file, the line and what was found there.
  void errorsNameTheLine_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("message");
    const ForceRecord r = smallRecord();
    auto bytes = [](const std::string& s) { return QByteArray(s.data(), static_cast<qsizetype>(s.size())); };
    auto row = [&](const char* name, const ForceUffLayout& l, const std::string& prefix, const QString& message) {
      QTest::newRow(name) << bytes(prefix + mx::test::forceRecordUff(r, l)) << message;
    };
    const ForceUffLayout ok;
    // Fx's dataset: "-1" line 1, "58" line 2, records 1-11 lines 3-13, record 12 lines 14-15.
    const std::string full = mx::test::forceRecordUff(r);
    QTest::newRow("truncated record") << bytes(full.substr(0, full.find("    -1\n    -1") - 41))
                                      << "cut.unv: line 14: truncated data: expected 4 values (4 points, record 7 at "
                                         "line 9), found 2 before the end of the file";
    ForceUffLayout l = ok;
    l.present = {false, true, true};
    row("missing x", l, "",
        "cut.unv: no time response of Fx: expected a dataset 58 of function type 1 (record 6) with response "
        "direction +-1; a cut needs Fx, Fy and Fz (0 dataset(s) 58 of another function type or direction skipped)");
    l.present = {true, false, true};
    row("missing y", l, "", "cut.unv: no time response of Fy");
    l.present = {true, true, false};
    row("missing z", l, "", "cut.unv: no time response of Fz");
    mx::test::Uff58Text frf;
    frf.data = {" 1.0 2.0 3.0 4.0"};
    QTest::newRow("FRFs only") << bytes(frf.text() + frf.text() + frf.text())
                               << "cut.unv: no time response of Fx: expected a dataset 58 of function type 1 (record "
                                  "6) with response direction +-1; a cut needs Fx, Fy and Fz (3 dataset(s) 58 of "
                                  "another function type or direction skipped)";
    l = ok;
    l.force_units = "g";
    row("not force units", l, "", "cut.unv: line 11: expected force units N, kN or lbf (record 9), found 'g'");
    l = ok;
    l.time_units = "Hz";
    row("not time units", l, "", "cut.unv: line 10: expected time units s or ms (record 8), found 'Hz'");
    l = ok;
    l.directions = {1, 1, 3};
    row("x twice", l, "",
        "cut.unv: line 23: a second time response of Fx (response direction 1, record 6): expected one per force, "
        "the first is the dataset at line 2");
    row("junk", ok, "hello\n", "cut.unv: line 1: expected '    -1' opening a dataset, found 'hello'");
    auto with = [&](auto edit) {
      mx::test::Uff58Text t;
      t.function_type = 1;
      t.response_dir = 1;
      t.reference_dir = 0;
      t.ordinate_type = 4;
      t.points = 2;
      t.x_increment = 0.001;
      t.abscissa_type = 17;
      t.abscissa_units = "s";
      t.numerator_type = 13;
      t.numerator_units = "N";
      t.data = {" 1.0 2.0"};
      edit(t);
      return bytes(t.text() + mx::test::forceDataset(r.t_s, r.fy_n, 1, ok) +
                   mx::test::forceDataset(r.t_s, r.fz_n, 2, ok));
    };
    QTest::newRow("acceleration") << with([](auto& t) { t.numerator_type = 12; })
                                  << "cut.unv: line 11: expected a force (record 9 specific data type 13 excitation "
                                     "force or 9 reaction force), found 12";
    QTest::newRow("frequency abscissa") << with([](auto& t) {
      t.abscissa_type = 18;
    }) << "cut.unv: line 10: expected a time abscissa (record 8 specific data type 17 or 0), found 18";
    QTest::newRow("complex") << with([](auto& t) {
      t.ordinate_type = 6;
      t.data = {" 1.0 0.0 2.0 0.0"};
    }) << "cut.unv: line 9: expected a real force (record 7 ordinate data type 2 or 4), found 6";
    QTest::newRow("one sample") << with([](auto& t) {
      t.points = 1;
      t.data = {" 1.0"};
    }) << "cut.unv: line 17: Fy has 4 points, Fx 1 (dataset at line 2): the three forces must be sampled together";
    QTest::newRow("other times")
        << with([](auto& t) {
             t.points = 4;
             t.x_increment = 0.002;
             t.data = {" 1.0 2.0 3.0 4.0"};
           })
        << "cut.unv: line 17: time of Fy point 2 = 0.001 s, of Fx 0.002 s (dataset at line 2): the three forces "
           "must be sampled together";
    QTest::newRow("force too large") << with([](auto& t) {
      t.numerator_units = "kN";
      t.data = {" 1.0 2.0E+04"};
    }) << "cut.unv: line 2: Fx of point 2 = 20000000 N: must be within ±1e7 N";
    QTest::newRow("time too large") << with([](auto& t) { t.x_min = 2e6; })
                                    << "cut.unv: line 2: time of point 1 = 2000000 s: must be within ±1e6 s";
    QTest::newRow("uneven times repeated") << with([](auto& t) {
      t.spacing = 0;
      t.data = {" 0.0 1.0 0.0 2.0"};
    }) << "cut.unv: line 14: expected increasing times, found 0 after 0";
    QTest::newRow("zero increment") << with([](auto& t) { t.x_increment = 0.0; })
                                    << "cut.unv: line 9: expected an abscissa increment > 0 (times increasing, "
                                       "record 7)";
    ForceUffLayout binary = ok;
    binary.binary = true;
    QTest::newRow("58b truncated") << bytes(mx::test::forceDataset(r.t_s, r.fx_n, 0, binary, 40))
                                   << "cut.unv: binary block of the dataset at line 2, byte 39: truncated binary "
                                      "block: expected 40 bytes, found the end of the file";
    QTest::newRow("58b count") << bytes(mx::test::forceDataset(r.t_s, r.fx_n, 0, binary, 24))
                               << "cut.unv: binary block of the dataset at line 2, byte 0: point count does not "
                                  "match the header: the block holds 24 bytes, expected 32";
  }
  void errorsNameTheLine() {
    QFETCH(QByteArray, text);
    QFETCH(QString, message);
    const QString error = inputError(text.toStdString());
    QVERIFY2(error.startsWith(message), qPrintable(error));
  }

  void oneSampleIsNotARecord() {
    ForceRecord r = smallRecord();
    for (auto* v : {&r.t_s, &r.fx_n, &r.fy_n, &r.fz_n}) v->resize(1);
    QCOMPARE(inputError(mx::test::forceRecordUff(r)),
             QString("cut.unv: fewer than 2 samples: expected a record of whole revolutions"));
  }
};

MX_REGISTER_TEST(TestForceRecordUff)
#include "test_force_record_uff.moc"
