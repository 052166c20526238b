// millexpert-plot: renders lobe curves printed by "millexpert-cli lobes" into a PNG or PDF chart, so
// that scripts and reports get the same plots as the GUI (QCustomPlot, offscreen).
//   millexpert-plot OUT.png [--title T] [--max-depth MM] FILE.json[=LABEL] ...
//   millexpert-plot OUT.png --control PROJECT --beta B          figures 9-12 (2006 paper) for one beta
//   millexpert-plot OUT.png --control PROJECT --jc FROM:TO:STEP figure 13, J_c(beta)
#include <qcustomplot.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <clocale>
#include <cmath>
#include <limits>

#include "control_figures.h"
#include "core/invalid_input.h"
#include "document/input_files.h"
#include "document/output_file.h"
#include "lobe_chart_view.h"

namespace {

bool addCurve(QCustomPlot& plot, const QString& spec, int index, QString& error) {
  const QString path = spec.section('=', 0, 0);
  QByteArray bytes;
  try {
    bytes = mx::app::readBoundedFile(path, mx::app::kPlotInputFileLimit);
  } catch (const mx::InvalidInput& e) {
    error = path + ": " + QString::fromStdString(e.what());
    return false;
  }
  const QJsonObject root = QJsonDocument::fromJson(bytes).object();
  const QJsonArray speeds = root.value("speed_rpm").toArray(), depths = root.value("blim_mm").toArray();
  if (speeds.isEmpty() || speeds.size() != depths.size()) {
    error = path + ": not the output of 'millexpert-cli lobes' (speed_rpm / blim_mm)";
    return false;
  }
  QVector<double> x, y;
  for (qsizetype i = 0; i < speeds.size(); ++i) {
    x.push_back(speeds[i].toDouble());
    y.push_back(depths[i].isNull() ? std::numeric_limits<double>::quiet_NaN() : depths[i].toDouble());
  }
  QCPGraph* graph = plot.addGraph();
  const QString label = spec.contains('=') ? spec.section('=', 1)
                                           : QString("%1 %2").arg(root.value("tool").toString(),
                                                                  root.value("method").toString().toUpper());
  graph->setName(label);
  graph->setPen(QPen(mx::widgets::LobeChartView::toolColor(index / 2), 2.0, index % 2 ? Qt::DashLine : Qt::SolidLine));
  graph->setData(x, y, true);
  return true;
}

// OUT is never one of the files read, nor a device, FIFO or directory (document/output_file.h).
QString outputProblem(const QStringList& args, const QString& control_project) {
  if (args.isEmpty()) return {};
  QList<mx::app::NamedPath> inputs;
  if (!control_project.isEmpty()) inputs.append({"--control", control_project});
  for (qsizetype i = 1; i < args.size(); ++i) inputs.append({"a curve file", args[i].section('=', 0, 0)});
  return mx::app::outputPathsProblem({{"OUT", args.front()}}, inputs);
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  std::setlocale(LC_NUMERIC, "C");
  QCommandLineParser parser;
  parser.setApplicationDescription("Render 'millexpert-cli lobes' JSON files into a chart.");
  parser.addHelpOption();
  parser.addPositionalArgument("out", "Output .png or .pdf");
  parser.addPositionalArgument("curves", "FILE.json[=LABEL] ...; curves 2k and 2k+1 share a colour (solid, dashed).");
  parser.addOption({"title", "Chart title.", "TEXT"});
  parser.addOption({"max-depth", "Upper end of the depth axis [mm].", "MM"});
  parser.addOption({"control", "Adaptive force control figures of this project's control section.", "PROJECT"});
  parser.addOption({"beta", "With --control: the closed loop for this beta (figures 9-12).", "B"});
  parser.addOption({"jc", "With --control: J_c against beta over FROM:TO:STEP (figure 13).", "FROM:TO:STEP"});
  parser.process(app);
  const QStringList args = parser.positionalArguments();
  if (const QString problem = outputProblem(args, parser.value("control")); !problem.isEmpty()) {
    QTextStream(stderr) << "millexpert-plot: " << problem << '\n';
    return 2;
  }
  if (parser.isSet("control")) {
    if (args.size() != 1) {
      QTextStream(stderr) << "millexpert-plot: --control needs exactly one OUT.png\n";
      return 2;
    }
    QString error;
    if (parser.isSet("jc")) {
      const QStringList p = parser.value("jc").split(':');
      if (p.size() != 3) {
        QTextStream(stderr) << "millexpert-plot: --jc = '" << parser.value("jc") << "': expected FROM:TO:STEP\n";
        return 2;
      }
      error =
          mx::gui::renderControlJc(parser.value("control"), p[0].toDouble(), p[1].toDouble(), p[2].toDouble(), args[0]);
    } else {
      error = mx::gui::renderControlResponse(parser.value("control"), parser.value("beta").toDouble(), args[0]);
    }
    if (!error.isEmpty()) {
      QTextStream(stderr) << "millexpert-plot: " << error << "\n";
      return 1;
    }
    return 0;
  }
  if (args.size() < 2) {
    QTextStream(stderr) << "millexpert-plot: need OUT and at least one curve file\n";
    return 2;
  }
  QCustomPlot plot;
  plot.resize(1200, 700);
  plot.xAxis->setLabel("Spindle speed N [rpm]");
  plot.yAxis->setLabel("Axial depth of cut b_lim [mm]");
  plot.legend->setVisible(true);
  if (parser.isSet("title")) {
    plot.plotLayout()->insertRow(0);
    plot.plotLayout()->addElement(0, 0, new QCPTextElement(&plot, parser.value("title"), QFont("DejaVu Sans", 12)));
  }
  for (int i = 1; i < args.size(); ++i) {
    QString error;
    if (!addCurve(plot, args[i], i - 1, error)) {
      QTextStream(stderr) << "millexpert-plot: " << error << '\n';
      return 2;
    }
  }
  plot.rescaleAxes();
  if (parser.isSet("max-depth"))
    plot.yAxis->setRange(0.0, parser.value("max-depth").toDouble());
  else
    plot.yAxis->setRangeLower(0.0);
  const QString& out = args.front();
  const bool ok =
      out.endsWith(".pdf", Qt::CaseInsensitive) ? plot.savePdf(out, 1200, 700) : plot.savePng(out, 1200, 700);
  if (!ok) {
    QTextStream(stderr) << "millexpert-plot: cannot write " << out << '\n';
    return 1;
  }
  return 0;
}
