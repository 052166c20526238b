// FRF file paths of the tools: relative to the project file's folder in the file, absolute in
// snapshots; saving to another folder names the same files from there.
#include <QDir>
#include <QTemporaryDir>

#include "document/frf_paths.h"
#include "document/project.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx::app;

namespace {

Project withFrfs(const QString& folder, const QString& x_file, const QString& y_file) {
  Project p = loadProject(mx::test::projectsPath("rubio2006-tool-selection.mxproj"));  // R1, R2
  p.folder = folder;
  p.tools[0].frf_x = FrfRefSpec{x_file, std::nullopt, std::nullopt, {}};
  p.tools[0].frf_y = FrfRefSpec{y_file, 1, QString("accelerance"), {}};
  return p;
}

QString savedFrfFile(const QString& path, const char* axis) {
  const QJsonObject root = mx::test::readJson(path);
  return root.value("tools").toArray().at(0).toObject().value(axis).toObject().value("file").toString();
}

}  // namespace

class TestFrfPaths : public QObject {
  Q_OBJECT

 private slots:
  void resolvesAgainstTheProjectFolder_data() {
    QTest::addColumn<QString>("folder");
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("expected");
    QTest::newRow("plain") << "/shop/jobs"
                           << "taps/T9-x.uff"
                           << "/shop/jobs/taps/T9-x.uff";
    QTest::newRow("dot dot") << "/shop/jobs"
                             << "../taps/./T9-x.uff"
                             << "/shop/taps/T9-x.uff";
    QTest::newRow("absolute kept") << "/shop/jobs"
                                   << "/data/T9-x.uff"
                                   << "/data/T9-x.uff";
    QTest::newRow("absolute cleaned") << "/shop/jobs"
                                      << "/data//x/../T9-x.uff"
                                      << "/data/T9-x.uff";
    QTest::newRow("no folder") << ""
                               << "T9-x.uff" << QDir::current().absoluteFilePath("T9-x.uff");
  }

  void resolvesAgainstTheProjectFolder() {
    QFETCH(QString, folder);
    QFETCH(QString, file);
    QFETCH(QString, expected);
    Project p;
    p.folder = folder;
    QCOMPARE(resolvedFrfPath(p, FrfRefSpec{file, std::nullopt, std::nullopt, {}}), expected);
  }

  void rewritesRelativePathsForANewFolder_data() {
    QTest::addColumn<QString>("to");
    QTest::addColumn<QString>("expected_x");
    QTest::newRow("same folder") << "/shop/jobs"
                                 << "taps/T9-x.uff";
    QTest::newRow("sibling") << "/shop/archive"
                             << "../jobs/taps/T9-x.uff";
    QTest::newRow("deeper") << "/shop/jobs/2026/dec"
                            << "../../taps/T9-x.uff";
    QTest::newRow("into taps") << "/shop/jobs/taps"
                               << "T9-x.uff";
  }

  void rewritesRelativePathsForANewFolder() {
    QFETCH(QString, to);
    QFETCH(QString, expected_x);
    const Project p = withFrfs("/shop/jobs", "taps/T9-x.uff", "/data/T9-y.uff");
    const Project moved = withFrfPathsRelativeTo(p, to);
    QCOMPARE(moved.folder, to);
    QCOMPARE(moved.tools[0].frf_x->file, expected_x);
    QCOMPARE(moved.tools[0].frf_y->file, QString("/data/T9-y.uff"));  // absolute stays absolute
    QCOMPARE(*moved.tools[0].frf_y->dataset, 1);                      // the rest of the reference is kept
    // invariant: every reference still names the same file
    QCOMPARE(resolvedFrfPath(moved, *moved.tools[0].frf_x), resolvedFrfPath(p, *p.tools[0].frf_x));
    QCOMPARE(resolvedFrfPath(moved, *moved.tools[0].frf_y), resolvedFrfPath(p, *p.tools[0].frf_y));
  }

  void snapshotsAreAbsolute() {
    const Project p = withFrfs("/shop/jobs", "taps/T9-x.uff", "/data/T9-y.uff");
    const Project snapshot = withAbsoluteFrfPaths(p);
    QCOMPARE(snapshot.tools[0].frf_x->file, QString("/shop/jobs/taps/T9-x.uff"));
    QCOMPARE(snapshot.tools[0].frf_y->file, QString("/data/T9-y.uff"));
    QCOMPARE(snapshot.tools.size(), std::size_t{2});
    QVERIFY(!snapshot.tools[1].frf_x);  // R2 has no tap test
  }

  void loadSetsTheFolderAndSaveAsRewrites() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkpath("jobs") && QDir(dir.path()).mkpath("archive/2026"));
    const QString first = dir.filePath("jobs/part.mxproj");
    saveProject(withFrfs(dir.filePath("jobs"), "taps/T9-x.uff", "taps/T9-y.uff"), first);
    QCOMPARE(savedFrfFile(first, "frf_x"), QString("taps/T9-x.uff"));
    const Project loaded = loadProject(first);
    QCOMPARE(loaded.folder, dir.filePath("jobs"));
    const QString second = dir.filePath("archive/2026/part.mxproj");
    saveProject(loaded, second);
    QCOMPARE(savedFrfFile(second, "frf_x"), QString("../../jobs/taps/T9-x.uff"));
    QCOMPARE(savedFrfFile(second, "frf_y"), QString("../../jobs/taps/T9-y.uff"));
    const Project reloaded = loadProject(second);
    QCOMPARE(resolvedFrfPath(reloaded, *reloaded.tools[0].frf_x), dir.filePath("jobs/taps/T9-x.uff"));
  }
};

MX_REGISTER_TEST(TestFrfPaths)
#include "test_frf_paths.moc"
