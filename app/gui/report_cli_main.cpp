// millexpert-report: the expert report of a project as PDF and/or HTML, without the GUI.
//   millexpert-report PROJECT [--pdf OUT.pdf] [--html OUT.html] [--embed-images] [--c c1,c2,c3]
//                     [--units metric|inch|QUANTITY=UNIT,...]
// Runs the expert system with simulation (Rules 4-6), the figure 4 sweep at the c3 in use, renders
// the figures offscreen and writes the report (ReportWriter). Exit codes as millexpert-cli:
// 0 ok; 1 computation failed (e.g. empty admissible space) or a file cannot be written;
// 2 bad input (arguments, weights off the simplex, bad project).
#include <QApplication>
#include <QCommandLineParser>
#include <QTemporaryDir>
#include <QTextStream>
#include <clocale>

#include "core/invalid_input.h"
#include "document/output_file.h"
#include "document/project.h"
#include "mx_version.h"
#include "report_data.h"
#include "report_writer.h"
#include "services/exit_code.h"
#include "services/expert_request.h"
#include "services/service_errors.h"

namespace {

int fail(const QString& message, int code) {
  QTextStream(stderr) << "millexpert-report: " << message << Qt::endl;
  return code;
}

int run(const QApplication& app) {
  QCommandLineParser parser;
  parser.setApplicationDescription("Write the expert report (ranking, q*, q**, cost terms, figures) of a project.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("project", "The .mxproj project file.");
  parser.addOptions({
      {"pdf", "Write the report as PDF (A4).", "OUT.pdf"},
      {"html", "Write the report as HTML; figures in the sibling folder OUT_files/.", "OUT.html"},
      {"embed-images", "HTML: embed the figures as data: URIs instead of the sibling folder."},
      {"c", "Tool-cost weights c1,c2,c3 (power, MRR, Delta N_s); sum 1. Default: the project's.", "C1,C2,C3"},
      {"units",
       "Shop units of the report: metric (default), inch, or either followed by QUANTITY=UNIT items, e.g. "
       "\"metric,power=kW\" (length mm|in, surface_speed m/min|ft/min, feed mm/min|in/min, chip_load "
       "mm/tooth|in/tooth, power W|kW|hp, force N|lbf, mrr cm3/min|in3/min). The GUI passes its own.",
       "UNITS"},
      {"project-name",
       "What the header and every footer name as the project file (default: PROJECT). The GUI writes its snapshot "
       "of the open project to a temporary file and names the project's own file here, or \"unsaved\".",
       "NAME"},
  });
  if (!parser.parse(app.arguments())) return fail(parser.errorText(), mx::app::kExitBadInput);
  if (parser.isSet("help")) {
    QTextStream(stdout) << parser.helpText();
    return mx::app::kExitOk;
  }
  if (parser.isSet("version")) {
    QTextStream(stdout) << "millexpert-report " << QCoreApplication::applicationVersion() << Qt::endl;
    return mx::app::kExitOk;
  }
  const QStringList positional = parser.positionalArguments();
  if (positional.size() != 1) return fail("expected exactly one PROJECT argument", mx::app::kExitBadInput);
  if (!parser.isSet("pdf") && !parser.isSet("html"))
    return fail("nothing to write: give --pdf and/or --html", mx::app::kExitBadInput);

  // The outputs are checked before any work: never the project, a tap test it names, each other, or a
  // device, FIFO or directory (document/output_file.h).
  QList<mx::app::NamedPath> outputs, inputs{{"PROJECT", positional.front()}};
  for (const QString flag : {"html", "pdf"})
    if (parser.isSet(flag)) outputs.append({"--" + flag, parser.value(flag)});
  inputs.append(mx::app::projectInputFiles(mx::app::loadProject(positional.front())));
  if (const QString problem = mx::app::outputPathsProblem(outputs, inputs); !problem.isEmpty())
    return fail(problem, mx::app::kExitBadInput);

  mx::gui::ReportOptions options;
  if (parser.isSet("units")) {
    QString why;
    const std::optional<mx::widgets::ShopUnits> units = mx::widgets::ShopUnits::fromText(parser.value("units"), &why);
    if (!units) return fail("--units: " + why, mx::app::kExitBadInput);
    options.units = *units;
  }
  if (parser.isSet("c")) {
    const std::vector<double> c = mx::app::parseWeightList("c", parser.value("c"), 3);
    options.c = std::array<double, 3>{c[0], c[1], c[2]};
  }
  QTemporaryDir work;
  if (!work.isValid()) return fail("cannot create a temporary folder for the figures", mx::app::kExitComputationFailed);
  options.image_dir = work.path();
  mx::gui::ReportData data = mx::gui::collectReportData(positional.front(), options);
  if (parser.isSet("project-name")) data.project_path = parser.value("project-name");
  const mx::gui::ReportWriter writer(data, options.units);
  if (parser.isSet("html"))
    writer.writeHtml(parser.value("html"),
                     parser.isSet("embed-images") ? mx::gui::HtmlImages::Embedded : mx::gui::HtmlImages::SiblingFolder);
  if (parser.isSet("pdf")) writer.writePdf(parser.value("pdf"));
  return mx::app::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");  // batch tool
  QApplication app(argc, argv);
  QApplication::setApplicationName("millexpert-report");
  QApplication::setApplicationVersion(mx::app::kVersion);
  std::setlocale(LC_NUMERIC, "C");
  try {
    return run(app);
  } catch (const mx::app::InputError& e) {
    return fail(QString::fromStdString(e.what()), e.exitCode());
  } catch (const mx::app::ComputationError& e) {
    return fail(QString::fromStdString(e.what()), e.exitCode());
  } catch (const mx::app::ProjectError& e) {
    return fail(QString::fromStdString(e.what()), e.exitCode());
  } catch (const mx::InvalidInput& e) {
    return fail(QString::fromStdString(e.what()), mx::app::kExitBadInput);
  } catch (const std::exception& e) {
    return fail(QString::fromStdString(e.what()), mx::app::kExitComputationFailed);
  }
}
