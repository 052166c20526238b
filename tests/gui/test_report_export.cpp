// The expert report: built for the Rubio 2006 project, the HTML has real
// tables with captions and the three figures as PNG files; the PDF, turned into text by pdftotext
// (poppler-utils), names the project, the tools, q* with units, the sections and captions, and the
// minimum cost of R1 as the engine computes it. millexpert-report refuses bad weights with exit 2, and
// outputs that are the project, each other, or not a regular file.
#include <sys/stat.h>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <memory>

#include "document/project.h"
#include "expert/expert_session.h"
#include "report_builder.h"
#include "report_data.h"
#include "report_writer.h"
#include "services/expert_request.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx::gui;

namespace {

using mx::test::kRubio;

QString readText(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

bool isPng(const QString& path) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) && file.size() > 100 && file.read(8) == QByteArray("\x89PNG\r\n\x1a\n", 8);
}

QString reportExecutable() {
  return QFileInfo(MX_CLI_PATH).absoluteDir().filePath("gui/millexpert-report");
}

}  // namespace

class TestReportExport : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    QVERIFY(QDir(dir_.path()).mkpath("work"));
    ReportOptions options;
    options.image_dir = dir_.filePath("work");
    data_ = std::make_unique<ReportData>(collectReportData(kRubio, options));
    html_ = dir_.filePath("report.html");
    pdf_ = dir_.filePath("report.pdf");
    const ReportWriter writer(*data_);
    writer.writeHtml(html_);
    writer.writePdf(pdf_);
    QVERIFY(QFileInfo(pdf_).size() > 1000);
  }

  void htmlHasTablesCaptionsAndFigures() {
    const QString html = readText(html_);
    QVERIFY(html.contains("<table"));
    QVERIFY(html.count("<caption>") >= 5);
    QVERIFY(html.contains("<caption>Table 4. Ranking"));
    QVERIFY(html.contains("[rpm]") && html.contains("[mm/tooth]") && html.contains("[W]"));
    QVERIFY(html.contains("MillExpert " + data_->version));
    QVERIFY(html.contains("Pitch [deg]") && html.contains("Runout [\u00b5m]") && html.contains(">uniform<"));
    const QRegularExpression img("<img src=\"([^\"]+)\"");
    QStringList sources;
    for (auto it = img.globalMatch(html); it.hasNext();) sources << it.next().captured(1);
    QCOMPARE(sources.size(), 3);
    for (const QString& src : sources) {
      const QString file = QFileInfo(html_).dir().filePath(src);
      QVERIFY2(QFileInfo(file).isRelative() == false && isPng(file), qPrintable(file + ": missing or not a PNG"));
      QVERIFY2(file.startsWith(ReportWriter::imageFolder(html_)), qPrintable(file));
    }
    for (const char* figure : {"Figure 1.", "Figure 2.", "Figure 3."}) QVERIFY(html.contains(figure));
  }

  // The material's edge forces, process damping and library entry appear when the project gives them.
  void materialRowsShowEdgeForcesAndProcessDamping() {
    QVERIFY(QDir(dir_.path()).mkpath("damped"));
    ReportOptions options;
    options.image_dir = dir_.filePath("damped");
    const ReportData damped = collectReportData(MX_PROJECTS_DIR "/process-damping-low-speed.mxproj", options);
    const QString html = dir_.filePath("damped.html");
    ReportWriter(damped).writeHtml(html);
    const QString text = readText(html);
    for (const QString& s :
         {QString("Tangential edge force K<sub>te</sub>"), QString("Radial edge force K<sub>re</sub>"),
          QString(">46.00<"), QString("Process damping C<sub>i</sub>"), QString(">100000<"), QString(">Ti-6Al-4V<")})
      QVERIFY2(text.contains(s), qPrintable("the report lacks '" + s + "'"));
    QVERIFY(!readText(html_).contains("edge force"));  // the Rubio case has K_t and K_r alone
  }

  void embeddedHtmlIsSelfContained() {
    const QString path = dir_.filePath("embedded.html");
    ReportWriter(*data_).writeHtml(path, HtmlImages::Embedded);
    const QString html = readText(path);
    QCOMPARE(html.count("<img src=\"data:image/png;base64,"), 3);
    QVERIFY(!QFileInfo::exists(ReportWriter::imageFolder(path)));
  }

  void pdfTextHasTheContent() {
    const QString pdftotext = QStandardPaths::findExecutable("pdftotext");
    if (pdftotext.isEmpty())
      QSKIP("pdftotext not found: install poppler-utils (packaging/bootstrap.sh does) to check the PDF text");
    QProcess process;
    process.start(pdftotext, {"-layout", pdf_, "-"});
    QVERIFY(process.waitForFinished(30000));
    QCOMPARE(process.exitCode(), 0);
    const QString text = QString::fromUtf8(process.readAllStandardOutput());

    // Expected values straight from the engine.
    const mx::app::Project project = mx::app::loadProject(kRubio);
    const mx::app::ExpertRequest request = mx::app::expertRequestFromProject(project);
    const mx::ExpertSession session(request.tools, request.settings);
    const mx::Ranking ranking = session.rank(request.weights.c);
    const QString selected = request.tool_ids[static_cast<qsizetype>(ranking.selected().tool)];
    double r1_cost = -1.0;
    for (const mx::ToolChoice& t : ranking.tools)
      if (request.tool_ids[static_cast<qsizetype>(t.tool)] == "R1") r1_cost = t.min_cost;
    QVERIFY(r1_cost > 0.0);
    QCOMPARE(selected, QString("R1"));
    QCOMPARE(mx::revPerSToRpm(ranking.selected().q.speed_rev_per_s), 5800.0);

    const QStringList expected{project.name,
                               "R1",
                               "R2",
                               "5800",
                               "rpm",
                               "mm/tooth",
                               "N/mm²",
                               "Ranking",
                               "Table 4. Ranking",
                               "Figure 1.",
                               "Figure 2.",
                               "Figure 3.",
                               "q**",
                               "Rule 6",
                               ReportBuilder::formatCost(r1_cost),
                               "MillExpert " + data_->version,
                               "page 1 /"};
    for (const QString& s : expected) QVERIFY2(text.contains(s), qPrintable("PDF text lacks '" + s + "'"));
    // The ranking row of R1: rank, tool, min cost, ..., q* speed.
    const QRegularExpression row("\\b1\\s+R1\\s+" + QRegularExpression::escape(ReportBuilder::formatCost(r1_cost)) +
                                 "\\s.*\\s5800\\s");
    QVERIFY2(row.match(text).hasMatch(), qPrintable(text.left(4000)));
  }

  void cliWritesTheReportAndRefusesBadWeights() {
    const QString exe = reportExecutable();
    QVERIFY2(QFileInfo::exists(exe), qPrintable(exe + " not built: build the target millexpert-report"));
    QProcess bad;
    bad.start(exe, {kRubio, "--pdf", dir_.filePath("bad.pdf"), "--c", "0.5,0.5,0.5"});
    QVERIFY(bad.waitForFinished(30000));
    QCOMPARE(bad.exitCode(), 2);
    const QString message = QString::fromUtf8(bad.readAllStandardError());
    QVERIFY2(message.contains("--c") && message.contains("sum"), qPrintable(message));
    QVERIFY(!QFileInfo::exists(dir_.filePath("bad.pdf")));

    QProcess none;
    none.start(exe, {kRubio});
    QVERIFY(none.waitForFinished(30000));
    QCOMPARE(none.exitCode(), 2);

    QProcess good;
    const QString html = dir_.filePath("cli.html");
    good.start(exe, {kRubio, "--html", html, "--embed-images", "--c", "0.3,0.625,0.075"});
    QVERIFY(good.waitForFinished(60000));
    QVERIFY2(good.exitCode() == 0, good.readAllStandardError().constData());
    QVERIFY(readText(html).contains("(0.3, 0.625, 0.075)"));
  }

  // The report in the GUI's shop units (millexpert-report --units): every unit-bearing head and value
  // converts; bad units exit 2 before any work.
  void reportInShopUnits() {
    const mx::widgets::ShopUnits inch = mx::widgets::ShopUnits::inch();
    const QString path = dir_.filePath("inch.html");
    ReportWriter(*data_, inch).writeHtml(path, HtmlImages::Embedded);
    const QString html = readText(path);
    for (const char* head : {"q* b [in]", "q* s<sub>t</sub> [in/tooth]", "Peak power [hp]", "MRR [in\u00b3/min]",
                             "D [in]", "axial depth b in in."})
      QVERIFY2(html.contains(QString::fromUtf8(head)), head);
    QVERIFY(!html.contains("[mm/tooth]") && !html.contains("[W]"));
    const mx::ExpertPoint& q = data_->result.ranking.selected().q;
    QVERIFY(html.contains(">" + inch.number(mx::widgets::Quantity::Length, q.depth_m * 1e3) + "<"));
    QVERIFY(html.contains(">" + inch.number(mx::widgets::Quantity::Power, q.power_w) + "<"));

    QProcess bad;
    bad.start(reportExecutable(), {kRubio, "--html", dir_.filePath("bad-units.html"), "--units", "power=PS"});
    QVERIFY(bad.waitForFinished(30000));
    QCOMPARE(bad.exitCode(), 2);
    const QString message = QString::fromUtf8(bad.readAllStandardError());
    QVERIFY2(message.startsWith("millexpert-report: --units: units item 'power=PS': unknown power unit 'PS' "
                                "(allowed: W, kW, hp)"),
             qPrintable(message));
    QVERIFY(!QFileInfo::exists(dir_.filePath("bad-units.html")));
  }

  // The report's outputs are checked before any work (document/output_file.h): never the project, each
  // other, or a device, FIFO or directory; the folder is unchanged afterwards.
  void cliRefusesOutputsThatWouldDestroyInputs_data() {
    QTest::addColumn<QStringList>("outputs");  // "@name": a file of the test's folder
    QTest::addColumn<QString>("flag");
    QTest::addColumn<QString>("why");
    QTest::newRow("project as --pdf") << QStringList{"--pdf", "@p.mxproj"} << "--pdf"
                                      << "the same file as PROJECT";
    QTest::newRow("--html as --pdf") << QStringList{"--html", "@r.html", "--pdf", "@r.html"} << "--pdf"
                                     << "the same file as --html";
    QTest::newRow("/dev/null") << QStringList{"--pdf", "/dev/null"} << "--pdf"
                               << "a character device, not a regular file";
    QTest::newRow("FIFO") << QStringList{"--html", "@fifo"} << "--html"
                          << "a FIFO, not a regular file";
    QTest::newRow("folder") << QStringList{"--pdf", "@folder"} << "--pdf"
                            << "a directory, not a regular file";
  }
  void cliRefusesOutputsThatWouldDestroyInputs() {
    QFETCH(QStringList, outputs);
    QFETCH(QString, flag);
    QFETCH(QString, why);
    QTemporaryDir dir;
    const QString project = dir.filePath("p.mxproj");
    QVERIFY(QFile::copy(kRubio, project));
    QVERIFY(QDir(dir.path()).mkdir("folder"));
    QVERIFY(::mkfifo(QFile::encodeName(dir.filePath("fifo")).constData(), 0600) == 0);
    const QByteArray original = readText(project).toUtf8();
    const QStringList before = QDir(dir.path()).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot);
    outputs.replaceInStrings(QRegularExpression("^@"), dir.path() + "/");
    QProcess report;
    report.start(reportExecutable(), QStringList{project} + outputs);
    QVERIFY(report.waitForFinished(30000));
    QCOMPARE(report.exitCode(), 2);
    const QString message = QString::fromUtf8(report.readAllStandardError());
    QVERIFY2(message.startsWith("millexpert-report: " + flag + " = '") && message.contains(why), qPrintable(message));
    QCOMPARE(readText(project).toUtf8(), original);
    QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::System | QDir::NoDotAndDotDot), before);
  }

 private:
  QTemporaryDir dir_;
  std::unique_ptr<ReportData> data_;
  QString html_, pdf_;
};

MX_REGISTER_TEST(TestReportExport)
#include "test_report_export.moc"
