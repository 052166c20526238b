// millexpert-plot: renders lobe curves printed by "millexpert-cli lobes" into a PNG or PDF chart, so
// that scripts and reports get the same plots as the GUI (QCustomPlot, offscreen).
//   millexpert-plot OUT.png [--title T] [--max-depth MM] FILE.json[=LABEL] ...
//   millexpert-plot OUT.png --control PROJECT --beta B          figures 9-12 (2006 paper) for one beta
//   millexpert-plot OUT.png --control PROJECT --jc FROM:TO:STEP figure 13, J_c(beta)
//   millexpert-plot OUT.png --beta-study STUDY.json             J_c(beta) per tau_c, both readings of eq. 34
//     (STUDY.json: the output of "millexpert-cli control PROJECT --beta-study")
#include <qcustomplot.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <algorithm>
#include <clocale>
#include <cmath>
#include <limits>
#include <vector>

#include "control_figures.h"
#include "core/invalid_input.h"
#include "document/input_files.h"
#include "document/output_file.h"
#include "lobe_chart_view.h"
#include "mx_version.h"

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

// J_c(beta) of the beta-FROH study, one panel per reading of eq. 34, one colour per tau_c, over the stable-zero
// betas (figure 13's range), each tau_c's zero threshold a dotted line of its colour; the paper's minimum (-0.3)
// and threshold (-0.6) in grey.
QString renderBetaStudy(const QString& path, const QString& out) {
  QByteArray bytes;
  try {
    bytes = mx::app::readBoundedFile(path, mx::app::kPlotInputFileLimit);
  } catch (const mx::InvalidInput& e) {
    return path + ": " + QString::fromStdString(e.what());
  }
  const QJsonObject root = QJsonDocument::fromJson(bytes).object();
  const QJsonArray betas = root.value("beta").toArray(), rows = root.value("rows").toArray();
  if (betas.isEmpty() || rows.isEmpty())
    return path + ": not the output of 'millexpert-cli control --beta-study' (beta / rows)";
  QCustomPlot plot;
  plot.resize(1400, 1000);
  plot.plotLayout()->clear();
  plot.setAutoAddPlottableToLegend(false);
  const QStringList titles = {"eq. 34 against the plant output's own samples (ripple between samples)",
                              "eq. 34 against the reference model's samples F_m(kT)"};
  const double T_ms = root.value("sampling_period_s").toDouble() * 1e3;
  auto* legend = new QCPLegend;  // below both panels, filled from the first; in the layout before any item
  plot.plotLayout()->addElement(4, 0, legend);
  legend->setFillOrder(QCPLayoutGrid::foRowsFirst);
  legend->setWrap(3);
  for (int panel = 0; panel < 2; ++panel) {
    auto* rect = new QCPAxisRect(&plot);
    plot.plotLayout()->addElement(2 * panel, 0, new QCPTextElement(&plot, titles[panel], QFont("DejaVu Sans", 11)));
    plot.plotLayout()->addElement(2 * panel + 1, 0, rect);
    rect->axis(QCPAxis::atBottom)->setLabel("FROH gain β [-]");
    rect->axis(QCPAxis::atLeft)->setLabel("J_c [N·s]");
    rect->axis(QCPAxis::atBottom)->setRange(-1.0, 1.0);
    double lo = INFINITY, hi = 0.0;
    std::vector<double> all;
    for (qsizetype k = 0; k < rows.size(); ++k) {
      const QJsonObject row = rows[k].toObject();
      const QJsonArray jc = row.value("readings").toArray()[panel].toObject().value("Jc").toArray();
      const QJsonArray unstable = row.value("unstable_zero").toArray();
      QVector<double> x, y;
      for (qsizetype i = 0; i < betas.size() && i < jc.size(); ++i) {
        x.push_back(betas[i].toDouble());
        const bool stable = !unstable[i].toBool() && !jc[i].isNull();
        y.push_back(stable ? jc[i].toDouble() : std::numeric_limits<double>::quiet_NaN());
        if (stable) all.push_back(jc[i].toDouble());
      }
      const QColor colour = mx::widgets::LobeChartView::toolColor(static_cast<int>(k));
      QCPGraph* graph = plot.addGraph(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
      const double tau = row.value("tau_c_ms").toDouble();
      graph->setName(QString("τ_c = %1 ms = T/%2, zero threshold β* = %3")
                         .arg(tau, 0, 'f', 2)
                         .arg(T_ms / tau, 0, 'f', 2)
                         .arg(row.value("threshold_beta").toDouble(), 0, 'f', 3));
      graph->setPen(QPen(colour, 2.0));
      graph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, 4));
      graph->setData(x, y, true);
      if (panel == 0) graph->addToLegend(legend);
      auto* threshold = new QCPItemStraightLine(&plot);
      threshold->setClipAxisRect(rect);
      for (auto* p : {threshold->point1, threshold->point2}) p->setAxes(graph->keyAxis(), graph->valueAxis());
      threshold->point1->setCoords(row.value("threshold_beta").toDouble(), 0.0);
      threshold->point2->setCoords(row.value("threshold_beta").toDouble(), 1.0);
      threshold->setPen(QPen(colour, 1.5, Qt::DotLine));
    }
    // the 5th to 95th percentile, padded: a few near-divergent runs reach 30 times the typical J_c
    std::sort(all.begin(), all.end());
    if (!all.empty()) {
      lo = all[all.size() / 20];
      hi = all[all.size() - 1 - all.size() / 20];
    }
    rect->axis(QCPAxis::atLeft)->setRange(std::max(0.0, lo - 0.3 * (hi - lo)), hi + 0.3 * (hi - lo));
    for (double b : {-0.3, -0.6}) {
      auto* line = new QCPItemStraightLine(&plot);
      line->setClipAxisRect(rect);
      for (auto* p : {line->point1, line->point2})
        p->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
      line->point1->setCoords(b, 0.0);
      line->point2->setCoords(b, 1.0);
      line->setPen(QPen(QColor(120, 120, 120), 2.0, b == -0.3 ? Qt::DashLine : Qt::DashDotLine));
    }
  }
  auto* paper = new QCPTextElement(&plot,
                                   "grey dashed: the paper's J_c minimum (β ≈ -0.3, figure 13); grey "
                                   "dash-dot: its zero threshold (-0.6); dotted: each τ_c's threshold; "
                                   "curves over the stable-zero β only; J_c axes clipped to the 5-95 % range",
                                   QFont("DejaVu Sans", 9));
  plot.plotLayout()->addElement(5, 0, paper);
  plot.plotLayout()->setRowStretchFactor(0, 0.01);
  plot.plotLayout()->setRowStretchFactor(2, 0.01);
  plot.plotLayout()->setRowStretchFactor(4, 0.01);
  plot.plotLayout()->setRowStretchFactor(5, 0.01);
  plot.replot();
  return plot.savePng(out, 1400, 1000) ? QString() : out + ": cannot write";
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
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");  // batch tool
  QApplication app(argc, argv);
  QApplication::setApplicationName("millexpert-plot");
  QApplication::setApplicationVersion(mx::app::kVersion);
  std::setlocale(LC_NUMERIC, "C");
  QCommandLineParser parser;
  parser.setApplicationDescription("Render 'millexpert-cli lobes' JSON files into a chart.");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument("out", "Output .png or .pdf");
  parser.addPositionalArgument("curves", "FILE.json[=LABEL] ...; curves 2k and 2k+1 share a colour (solid, dashed).");
  parser.addOption({"title", "Chart title.", "TEXT"});
  parser.addOption({"max-depth", "Upper end of the depth axis [mm].", "MM"});
  parser.addOption({"control", "Adaptive force control figures of this project's control section.", "PROJECT"});
  parser.addOption({"beta", "With --control: the closed loop for this beta (figures 9-12).", "B"});
  parser.addOption({"jc", "With --control: J_c against beta over FROM:TO:STEP (figure 13).", "FROM:TO:STEP"});
  parser.addOption({"beta-study", "J_c(beta) per tau_c from 'millexpert-cli control --beta-study' JSON.", "FILE"});
  parser.process(app);
  const QStringList args = parser.positionalArguments();
  if (const QString problem = outputProblem(args, parser.value("control")); !problem.isEmpty()) {
    QTextStream(stderr) << "millexpert-plot: " << problem << '\n';
    return 2;
  }
  if (parser.isSet("beta-study")) {
    if (args.size() != 1) {
      QTextStream(stderr) << "millexpert-plot: --beta-study needs exactly one OUT.png\n";
      return 2;
    }
    if (const QString problem =
            mx::app::outputPathsProblem({{"OUT", args[0]}}, {{"--beta-study", parser.value("beta-study")}});
        !problem.isEmpty()) {
      QTextStream(stderr) << "millexpert-plot: " << problem << '\n';
      return 2;
    }
    const QString error = renderBetaStudy(parser.value("beta-study"), args[0]);
    if (!error.isEmpty()) {
      QTextStream(stderr) << "millexpert-plot: " << error << "\n";
      return 1;
    }
    return 0;
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
