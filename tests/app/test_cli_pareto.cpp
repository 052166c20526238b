// millexpert-cli pareto: the fixed JSON interface on projects/rubio-pareto-case.mxproj, the flags
// (--w, --fine, --require, --auto-weights) and the exit-2 messages for a bad "pareto" section or flag.
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <cmath>

#include "support/cli_runner.h"
#include "support/json_mutation.h"
#include "test_main.h"

namespace {
const QString kCase = QStringLiteral(MX_PROJECTS_DIR "/rubio-pareto-case.mxproj");

QString caseWith(const QTemporaryDir& dir, const QStringList& mutations) {
  QFile in(kCase);
  in.open(QIODevice::ReadOnly);
  const QJsonObject root = mx::test::mutated(QJsonDocument::fromJson(in.readAll()).object(), mutations);
  const QString path = dir.filePath("p.mxproj");
  QFile out(path);
  out.open(QIODevice::WriteOnly);
  out.write(QJsonDocument(root).toJson());
  return path;
}

double sum(const QJsonArray& a) {
  double s = 0.0;
  for (const auto& v : a) s += v.toDouble();
  return s;
}
}  // namespace

class TestCliPareto : public QObject {
  Q_OBJECT
 private slots:
  void interface_data() {
    QTest::addColumn<QStringList>("flags");
    QTest::newRow("project weights") << QStringList{};
    QTest::newRow("--w") << QStringList{"--w", "0.1,0.6,0.1,0.2"};
    QTest::newRow("--fine") << QStringList{"--fine"};
    QTest::newRow("--require") << QStringList{"--require", "mrr_cm3_s=0.3:0.6"};
    QTest::newRow("--auto-weights") << QStringList{"--auto-weights"};
  }
  void interface() {
    QFETCH(QStringList, flags);
    const mx::test::CliRun r = mx::test::runCli(QStringList{"pareto", kCase} + flags);
    QVERIFY2(r.code == 0, qPrintable(r.err));
    for (const char* key : {"q", "feed_velocity_mm_s", "mrr_cm3_s", "tol", "surf", "ros", "eta", "power_W", "weights",
                            "pareto_set"})
      QVERIFY2(r.json.contains(key), key);
    const QJsonObject q = r.json["q"].toObject();
    for (const char* key : {"speed_rpm", "depth_mm", "feed_mm_per_tooth"}) QVERIFY2(q.contains(key), key);
    const QJsonArray w = r.json["weights"].toArray();
    QCOMPARE(w.size(), 4);
    QVERIFY(std::abs(sum(w) - 1.0) < 1e-6);
    for (const auto& v : w) QVERIFY(v.toDouble() >= -1e-12);
    QVERIFY(r.json["power_W"].toDouble() <= 2745.3 * (1 + 1e-6));
    QVERIFY(r.json["feed_velocity_mm_s"].toDouble() <= 25.0 * (1 + 1e-6));
    QVERIFY(r.json["j"].toDouble() >= r.json["coarse_j"].toDouble());
    QVERIFY(r.json["eta"].toDouble() > 0.0);
    const QJsonArray set = r.json["pareto_set"].toArray();
    QVERIFY(!set.isEmpty());
    const QJsonObject first = set.first().toObject();
    for (const char* key : {"q", "tol", "mrr_cm3_s", "surf", "ros"}) QVERIFY2(first.contains(key), key);
    if (flags.contains("--require")) {
      const double mrr = r.json["mrr_cm3_s"].toDouble();
      QVERIFY2(mrr >= 0.3 && mrr <= 0.6, qPrintable(QString::number(mrr)));
      QVERIFY(r.json["requirement"].toObject()["satisfied"].toBool());
    }
  }

  void errors_data() {
    QTest::addColumn<QStringList>("mutations");
    QTest::addColumn<QStringList>("flags");
    QTest::addColumn<QString>("message");
    QTest::newRow("no pareto section") << QStringList{"-pareto"} << QStringList{} << "section 'pareto' is missing";
    QTest::newRow("taylor K") << QStringList{"pareto/taylor/K=-1"} << QStringList{}
                              << "pareto.taylor.K = -1: must be a finite number > 0";
    QTest::newRow("roughness exponent") << QStringList{"pareto/roughness/feed_exponent=12"} << QStringList{}
                                        << "pareto.roughness.feed_exponent = 12: must be in [-10, 10]";
    QTest::newRow("missing exponent") << QStringList{"-pareto/taylor/depth_exponent"} << QStringList{}
                                      << "pareto.taylor.depth_exponent is missing";
    QTest::newRow("weights sum") << QStringList{"pareto/weights=[0.5,0.5,0.5,0.5]"} << QStringList{}
                                 << "pareto.weights: w = [0.5, 0.5, 0.5, 0.5]: the weights";
    QTest::newRow("fine divisions") << QStringList{"pareto/fine/divisions=0"} << QStringList{}
                                    << "pareto.fine.divisions = 0: must be an integer in [1, 100]";
    QTest::newRow("ascent step") << QStringList{"pareto/auto_weights/step=2"} << QStringList{}
                                 << "pareto.auto_weights.step = 2: must be in (0, 1]";
    QTest::newRow("unknown tool") << QStringList{"pareto/tool=\"X\""} << QStringList{}
                                  << "pareto.tool = 'X': no tool with that id";
    QTest::newRow("--w count") << QStringList{} << QStringList{"--w", "0.5,0.5"} << "expected 4 weights";
    QTest::newRow("--w simplex") << QStringList{} << QStringList{"--w", "0.5,0.5,0.5,-0.5"} << ">= 0";
    QTest::newRow("--require form") << QStringList{} << QStringList{"--require", "mrr_cm3_s=2"} << "--require = ";
    QTest::newRow("--require key") << QStringList{} << QStringList{"--require", "speed=1:2"}
                                   << "--require key = 'speed': must be one of mrr_cm3_s, tol, surf, ros";
    QTest::newRow("--require order") << QStringList{} << QStringList{"--require", "mrr_cm3_s=2:1"} << "LO <= HI";
  }
  void errors() {
    QFETCH(QStringList, mutations);
    QFETCH(QStringList, flags);
    QFETCH(QString, message);
    QTemporaryDir dir;
    const QString path = mutations.isEmpty() ? kCase : caseWith(dir, mutations);
    const mx::test::CliRun r = mx::test::runCli(QStringList{"pareto", path} + flags);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
  }

  // Unknown sections survive: the pareto section is preserved by the project loader (check passes).
  void projectChecks() {
    const mx::test::CliRun r = mx::test::runCli({"check", kCase});
    QVERIFY2(r.code == 0, qPrintable(r.err));
  }
};

MX_TEST_MAIN(TestCliPareto)
#include "test_cli_pareto.moc"
