#include "report_builder.h"

#include <cmath>
#include <optional>
#include <utility>

namespace mx::gui {

using widgets::perMinute;
using widgets::Quantity;

namespace {

const char* kStyle =
    "body { font-family: 'DejaVu Sans', sans-serif; font-size: 9pt; }\n"
    "h1 { font-size: 16pt; } h2 { font-size: 12pt; margin-top: 14px; }\n"
    "table.data { border-collapse: collapse; margin-bottom: 10px; }\n"
    "table.data th { background-color: #dde6f0; }\n"
    "caption, p.caption { font-weight: bold; text-align: left; margin-top: 8px; margin-bottom: 4px; }\n"
    "p.figcaption { text-align: center; margin-bottom: 12px; }\n"
    "p.footer { color: #555555; font-size: 8pt; border-top: 1px solid #999999; }\n";

QString esc(const QString& s) {
  return s.toHtmlEscaped();
}

// A per-tooth list ("70/110/70/110"), or `absent` when the tool has none.
QString perTooth(const std::optional<std::vector<double>>& values, const QString& absent) {
  if (!values) return absent;
  QStringList items;
  for (double v : *values) items << ReportBuilder::formatNumber(v, 1);
  return items.join('/');
}

QString rpm(double rev_per_s) {
  return ReportBuilder::formatNumber(revPerSToRpm(rev_per_s), 0);
}
QString weights(const double* v, std::size_t n) {
  QStringList parts;
  for (std::size_t i = 0; i < n; ++i) parts << QString::number(v[i], 'g', 6);
  return "(" + parts.join(", ") + ")";
}
QString optional(const std::optional<double>& v, int decimals, const QString& absent = "no limit") {
  return v ? ReportBuilder::formatNumber(*v, decimals) : absent;
}
// "1000 rpm: 2000 W; 3000 rpm: 4000 W" (machine.spindle_curve), in the shop unit of power.
QString curveRows(const std::vector<app::SpindleCurveRowSpec>& rows, const widgets::ShopUnits& u) {
  QStringList parts;
  for (const app::SpindleCurveRowSpec& r : rows)
    parts
        << QString("%1 rpm: %2").arg(ReportBuilder::formatNumber(r.speed_rpm, 0), u.format(Quantity::Power, r.power_W));
  return parts.join("; ");
}
// NF1's P_av: one value, or the speed-dependent limit (torque line, power curve) of the point's speed.
QString availablePowerMeaning(const SpindlePowerCurve& p, const QString& unit) {
  if (p.constant()) return QString("P<sub>av</sub> [%1]").arg(unit);
  return QString(
             "P<sub>av</sub>(N) = min(P<sub>max</sub>, 2\u03c0N T<sub>max</sub>, curve) at the point's speed; "
             "P<sub>max</sub> [%1]")
      .arg(unit);
}

}  // namespace

ReportBuilder::ReportBuilder(const ReportData& data, ReportFlavour flavour, ImageSource source,
                             const widgets::ShopUnits& units)
    : d_(data), flavour_(flavour), source_(std::move(source)), u_(units) {}

QString ReportBuilder::length(double m) const {
  return u_.number(Quantity::Length, m * 1e3);
}
QString ReportBuilder::chipLoad(double m) const {
  return u_.number(Quantity::ChipLoad, m * 1e3);
}
QString ReportBuilder::power(double w) const {
  return u_.number(Quantity::Power, w);
}
QString ReportBuilder::mrr(double m3_per_s) const {
  return u_.number(Quantity::RemovalRate, m3_per_s * 1e6 * 60.0);  // cm³/min
}
QString ReportBuilder::unit(Quantity q) const {
  return u_.symbol(q).toHtmlEscaped();
}

QString ReportBuilder::formatNumber(double value, int decimals) {
  return std::isfinite(value) ? QString::number(value, 'f', decimals) : QString("\u2014");
}

QString ReportBuilder::formatCost(double cost) {
  return formatNumber(cost, 4);
}

QString ReportBuilder::footer() const {
  return QString("MillExpert %1 \u00b7 report generated %2 \u00b7 %3")
      .arg(d_.version, d_.generated.toString("yyyy-MM-dd HH:mm"), d_.project_path);
}

QString ReportBuilder::table(const QString& caption, const QStringList& head, const QList<QStringList>& rows) const {
  const QString title = QString("Table %1. %2").arg(++tables_).arg(caption);
  QString out = "<table class=\"data\" border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">\n";
  if (flavour_ == ReportFlavour::Browser) out += "<caption>" + title + "</caption>\n<thead>";
  // QTextDocument has no <caption>: a header row spanning the table keeps the caption with the table
  // (and repeats it, with the column heads, on every page the table spans).
  else
    out += QString("<thead><tr><td colspan=\"%1\"><b>%2</b></td></tr>").arg(head.size()).arg(title);
  out += "<tr>";
  for (const QString& h : head) out += "<th bgcolor=\"#dde6f0\">" + h + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (const QStringList& row : rows) {
    out += "<tr>";
    for (const QString& cell : row) out += "<td>" + cell + "</td>";
    out += "</tr>\n";
  }
  return out + "</tbody></table>\n";
}

QString ReportBuilder::figure(const QString& image, const QString& caption) const {
  const QString title = QString("Figure %1.").arg(++figures_);
  return QString(
             "<p align=\"center\"><img src=\"%1\" width=\"640\" alt=\"%2\"></p>\n"
             "<p class=\"figcaption\" align=\"center\"><b>%2</b> %3</p>\n")
      .arg(esc(source_(image)), title, caption);
}

QString ReportBuilder::projectSection() const {
  const app::Project& p = d_.project;
  QList<QStringList> rows;
  rows << QStringList{"Project", esc(p.name), ""};
  if (p.machine) {
    const bool speed_dependent = p.machine->max_torque_Nm || p.machine->spindle_curve;
    rows << QStringList{speed_dependent ? "Spindle power P<sub>max</sub>" : "Spindle power P<sub>av</sub>",
                        power(p.machine->spindle_power_W), unit(Quantity::Power)};
    if (p.machine->max_torque_Nm)
      rows << QStringList{"Spindle torque T<sub>max</sub> (P<sub>av</sub> \u2264 2\u03c0N T<sub>max</sub>)",
                          formatNumber(*p.machine->max_torque_Nm, 2), "N\u00b7m"};
    if (p.machine->spindle_curve)
      rows << QStringList{"Spindle power curve (P<sub>av</sub> \u2264 curve)", curveRows(*p.machine->spindle_curve, u_),
                          "rpm: " + unit(Quantity::Power)};
    rows << QStringList{"Maximum spindle speed", optional(p.machine->max_spindle_rpm, 0), "rpm"};
    rows << QStringList{"Maximum feed rate",
                        p.machine->max_feed_mm_s ? u_.number(Quantity::Feed, perMinute(*p.machine->max_feed_mm_s))
                                                 : QString("no limit"),
                        unit(Quantity::Feed)};
  }
  if (p.material) {
    rows << QStringList{"Material", esc(p.material->name), ""};
    rows << QStringList{"Tangential coefficient K<sub>t</sub>", formatNumber(p.material->Kt_N_mm2, 1), "N/mm\u00b2"};
    rows << QStringList{"Radial ratio K<sub>r</sub>", formatNumber(p.material->Kr, 3), "\u2013"};
    const std::pair<const char*, const std::optional<double>*> edges[] = {
        {"Tangential edge force K<sub>te</sub>", &p.material->Kte_N_mm},
        {"Radial edge force K<sub>re</sub>", &p.material->Kre_N_mm},
        {"Axial edge force K<sub>ae</sub>", &p.material->Kae_N_mm}};
    for (const auto& [label, value] : edges)
      if (*value) rows << QStringList{label, formatNumber(**value, 2), "N/mm"};
    if (p.material->Ka_N_mm2)
      rows << QStringList{"Axial coefficient K<sub>a</sub>", formatNumber(*p.material->Ka_N_mm2, 1), "N/mm\u00b2"};
    if (p.material->process_damping_N_per_m)
      rows << QStringList{"Process damping C<sub>i</sub> (the ZOA leaves it out)",
                          formatNumber(*p.material->process_damping_N_per_m, 0), "N/m"};
    if (p.material->library) rows << QStringList{"From the materials library", esc(*p.material->library), ""};
  }
  if (p.operation) {
    rows << QStringList{"Operation", p.operation->milling == MillingDirection::Up ? "up milling" : "down milling", ""};
    if (p.operation->radial_immersion)
      rows << QStringList{"Radial immersion a/D", formatNumber(*p.operation->radial_immersion, 3), "\u2013"};
    if (p.operation->radial_depth_mm)
      rows << QStringList{"Radial depth of cut a", length(*p.operation->radial_depth_mm * 1e-3),
                          unit(Quantity::Length)};
    rows << QStringList{"Maximum feed per tooth",
                        p.operation->max_feed_per_tooth_mm > 0 ? chipLoad(p.operation->max_feed_per_tooth_mm * 1e-3)
                                                               : QString("no limit"),
                        unit(Quantity::ChipLoad)};
  }
  const ExpertGrid& g = d_.settings.grid;
  rows << QStringList{"Speed grid",
                      QString("%1 to %2, step %3")
                          .arg(rpm(g.speed_from_rev_per_s), rpm(g.speed_to_rev_per_s), rpm(g.speed_step_rev_per_s)),
                      "rpm"};
  rows << QStringList{"Depth grid", QString("b<sub>min</sub>/%1 steps").arg(g.depth_divisions), unit(Quantity::Length)};
  rows << QStringList{"Feed step", chipLoad(g.feed_step_m), unit(Quantity::ChipLoad)};
  rows << QStringList{
      "Stability method",
      d_.settings.stability.method == StabilityMethod::ZeroOrder ? "zeroth-order approximation" : "semi-discretization",
      ""};
  QString out = "<h2>1 Project, machine and tools</h2>\n";
  out += table("Project, machine, material and operation", {"Quantity", "Value", "Unit"}, rows);

  QList<QStringList> tools;
  for (const app::ToolSpec& t : p.tools) {
    bool first = true;
    const auto addModes = [&](const char* axis, const std::vector<app::ModeSpec>& modes) {
      for (std::size_t m = 0; m < modes.size(); ++m) {
        QStringList row;
        if (first)
          row << esc(t.id) << QString::number(t.teeth) << length(t.diameter_mm * 1e-3) << formatNumber(t.helix_deg, 1)
              << perTooth(t.pitch_deg, "uniform") << perTooth(t.runout_um, "\u2013");
        else
          row << ""
              << ""
              << ""
              << ""
              << ""
              << "";
        first = false;
        row << QString("%1%2").arg(axis).arg(m + 1) << formatNumber(modes[m].freq_Hz, 2)
            << formatNumber(modes[m].damping_pct, 2) << formatNumber(modes[m].stiffness_N_per_um, 3);
        tools << row;
      }
    };
    addModes("x", t.modes_x);
    addModes("y", t.modes_y);
  }
  out += table("Candidate tools and their modes (per axis)",
               {"Tool", "Teeth", QString("D [%1]").arg(unit(Quantity::Length)), "Helix [deg]", "Pitch [deg]",
                "Runout [\u00b5m]", "Mode", "f [Hz]", "\u03b6 [%]", "k [N/\u00b5m]"},
               tools);

  const CostWeights& w = d_.weights;
  const CostWeights& after = d_.result.weights;
  const CostNormalisation& nf = d_.normalisation;
  QList<QStringList> rows3{
      {"c = (c1, c2, c3)", "tool cost weights: power, MRR, \u0394N<sub>s</sub> (eq. 13), requested",
       weights(w.c.data(), 3)},
      {"c after Rule 6", "after the malfunction loop", weights(after.c.data(), 3)},
      {"c<sub>r</sub> = (c1r, c2r, c3r)", "resultant cost weights: C, C<sub>t</sub>, C<sub>f</sub> (eq. 20)",
       weights(w.cr.data(), 3)},
      {"c<sub>t</sub> = (c1t, c2t)", "time-domain cost weights: t<sub>s</sub>, M<sub>p</sub> (eq. 18)",
       weights(w.ct.data(), 2)},
      {"c<sub>f</sub> = (c1f, c2f)", "frequency cost weights: R12h, R1ch (eq. 19)", weights(w.cf.data(), 2)},
      {"\u03b4 [1/s]", "lobe margin, Rule 1.1", formatNumber(d_.settings.stability.delta_per_s, 4)},
      {"\u03b1 [\u2013]", "depth margin, Rule 1.2", formatNumber(d_.settings.stability.alpha, 3)},
      {"NF1 = 1/P<sub>av</sub>", availablePowerMeaning(nf.available_power, unit(Quantity::Power)),
       power(nf.available_power.max_power_w)},
      {"NF2 = MRR<sub>max</sub>", QString("over all tools [%1]").arg(unit(Quantity::RemovalRate)),
       mrr(nf.max_mrr_m3_per_s)},
      {"NF3 = \u0394N<sub>s,max</sub>", "over all tools [rpm]", rpm(nf.max_speed_security)}};
  out += table("Weights, margins and normalisation factors", {"Symbol", "Meaning", "Value"}, rows3);
  return out;
}

QString ReportBuilder::rankingSection() const {
  const Ranking& r = d_.result.ranking;
  QList<QStringList> rows;
  int rank = 0;
  for (const ToolChoice& t : r.tools)
    rows << QStringList{QString::number(++rank),   esc(d_.toolId(t.tool)),  "<b>" + formatCost(t.min_cost) + "</b>",
                        formatCost(t.terms.power), formatCost(t.terms.mrr), formatCost(t.terms.speed_security),
                        rpm(t.q.speed_rev_per_s),  length(t.q.depth_m),     chipLoad(t.q.feed_per_tooth_m),
                        power(t.q.power_w),        mrr(t.q.mrr_m3_per_s),   rpm(t.q.speed_security)};
  QString out = "<h2>2 Ranking of the tools (Rule 4)</h2>\n";
  out += QString(
             "<p>Tools ranked by their minimum tool cost C (eq. 13) over the admissible space Q, at c = %1. "
             "q* = (N, b, s<sub>t</sub>) is each tool's cost-minimising point. Selected tool: <b>%2</b>.</p>\n")
             .arg(weights(r.c.data(), 3), esc(d_.selectedId()));
  out += table(
      QString("Ranking of the candidate tools by minimum cost C (c = %1)").arg(weights(r.c.data(), 3)),
      {"Rank", "Tool", "Min cost C [\u2013]", "c1 P/P<sub>av</sub> [\u2013]", "c2 MRR<sub>max</sub>/MRR [\u2013]",
       "c3 \u0394N<sub>s,max</sub>/\u0394N<sub>s</sub> [\u2013]", "q* N [rpm]",
       QString("q* b [%1]").arg(unit(Quantity::Length)), QString("q* s<sub>t</sub> [%1]").arg(unit(Quantity::ChipLoad)),
       QString("Peak power [%1]").arg(unit(Quantity::Power)), QString("MRR [%1]").arg(unit(Quantity::RemovalRate)),
       "\u0394N<sub>s</sub> [rpm]"},
      rows);
  for (std::size_t t : r.excluded) out += "<p>Excluded (empty admissible space): " + esc(d_.toolId(t)) + "</p>\n";
  return out;
}

QString ReportBuilder::selectionSection() const {
  const ToolChoice& sel = d_.result.ranking.selected();
  const std::optional<Refinement>& ref = d_.result.refinement;
  const RefinementCandidate* star = nullptr;
  if (ref)
    for (const RefinementCandidate& c : ref->candidates)
      if (c.q.speed_rev_per_s == sel.q.speed_rev_per_s && c.q.depth_m == sel.q.depth_m &&
          c.q.feed_per_tooth_m == sel.q.feed_per_tooth_m)
        star = &c;
  const RefinementCandidate* chosen = ref ? &ref->chosen() : nullptr;
  const auto terms = [&](const ExpertPoint& q) {
    return toolCostTerms(d_.result.weights.c, d_.normalisation, q.speed_rev_per_s, q.power_w, q.mrr_m3_per_s,
                         q.speed_security);
  };
  const CostTerms t1 = terms(sel.q);
  const CostTerms t2 = chosen ? terms(chosen->q) : CostTerms{};
  const QString none("\u2014");
  const auto col2 = [&](auto f) { return chosen ? f(*chosen) : none; };
  const auto col1 = [&](auto f) { return star ? f(*star) : none; };
  const auto row = [&](const QString& name, const QString& unit, const QString& a, const QString& b) {
    return QStringList{name, unit, a, b};
  };
  QList<QStringList> rows{
      row("Spindle speed N", "rpm", rpm(sel.q.speed_rev_per_s),
          col2([](const RefinementCandidate& c) { return rpm(c.q.speed_rev_per_s); })),
      row("Axial depth b", unit(Quantity::Length), length(sel.q.depth_m),
          col2([this](const RefinementCandidate& c) { return length(c.q.depth_m); })),
      row("Feed per tooth s<sub>t</sub>", unit(Quantity::ChipLoad), chipLoad(sel.q.feed_per_tooth_m),
          col2([this](const RefinementCandidate& c) { return chipLoad(c.q.feed_per_tooth_m); })),
      row("Peak power P", unit(Quantity::Power), power(sel.q.power_w),
          col2([this](const RefinementCandidate& c) { return power(c.q.power_w); })),
      row("MRR", unit(Quantity::RemovalRate), mrr(sel.q.mrr_m3_per_s),
          col2([this](const RefinementCandidate& c) { return mrr(c.q.mrr_m3_per_s); })),
      row("\u0394N<sub>s</sub>", "rpm", rpm(sel.q.speed_security),
          col2([](const RefinementCandidate& c) { return rpm(c.q.speed_security); })),
      row("Tool cost C (eq. 13)", "\u2013", formatCost(t1.total()), chosen ? formatCost(t2.total()) : none),
      row("&nbsp;&nbsp;c1 P/P<sub>av</sub>", "\u2013", formatCost(t1.power), chosen ? formatCost(t2.power) : none),
      row("&nbsp;&nbsp;c2 MRR<sub>max</sub>/MRR", "\u2013", formatCost(t1.mrr), chosen ? formatCost(t2.mrr) : none),
      row("&nbsp;&nbsp;c3 \u0394N<sub>s,max</sub>/\u0394N<sub>s</sub>", "\u2013", formatCost(t1.speed_security),
          chosen ? formatCost(t2.speed_security) : none),
      row("Time-domain cost C<sub>t</sub> (eq. 18)", "\u2013",
          col1([](const RefinementCandidate& c) { return formatCost(c.time_cost); }),
          col2([](const RefinementCandidate& c) { return formatCost(c.time_cost); })),
      row("Frequency cost C<sub>f</sub> (eq. 19)", "\u2013",
          col1([](const RefinementCandidate& c) { return formatCost(c.frequency_cost); }),
          col2([](const RefinementCandidate& c) { return formatCost(c.frequency_cost); })),
      row("Resultant cost C<sub>resultant</sub> (eq. 20)", "\u2013",
          col1([](const RefinementCandidate& c) { return formatCost(c.resultant); }),
          col2([](const RefinementCandidate& c) { return formatCost(c.resultant); })),
      row("Settling time t<sub>s</sub>", "ms",
          col1([](const RefinementCandidate& c) { return formatNumber(c.metrics.settling_time_s * 1e3, 2); }),
          col2([](const RefinementCandidate& c) { return formatNumber(c.metrics.settling_time_s * 1e3, 2); })),
      row("Overshoot M<sub>p</sub>", "%",
          col1([](const RefinementCandidate& c) { return formatNumber(c.metrics.overshoot * 100.0, 2); }),
          col2([](const RefinementCandidate& c) { return formatNumber(c.metrics.overshoot * 100.0, 2); })),
      row("R12h = A(2f<sub>tp</sub>)/A(f<sub>tp</sub>)", "\u2013",
          col1([](const RefinementCandidate& c) { return formatNumber(c.metrics.r12h, 4); }),
          col2([](const RefinementCandidate& c) { return formatNumber(c.metrics.r12h, 4); })),
      row("R1ch = A<sub>chatter</sub>/A(f<sub>tp</sub>)", "\u2013",
          col1([](const RefinementCandidate& c) { return formatNumber(c.metrics.r1ch, 4); }),
          col2([](const RefinementCandidate& c) { return formatNumber(c.metrics.r1ch, 4); })),
      row("Chatter (simulation verdict)", "",
          col1([](const RefinementCandidate& c) { return QString(c.metrics.chatter ? "yes" : "no"); }),
          col2([](const RefinementCandidate& c) { return QString(c.metrics.chatter ? "yes" : "no"); }))};

  QString out = "<h2>3 Selected cutting parameters (Rules 5 and 6)</h2>\n";
  out += QString(
             "<p>Tool <b>%1</b>. q* minimises the tool cost C; q** minimises the resultant cost C<sub>resultant</sub> "
             "over the %2 best points by C, each simulated in the time domain (c<sub>r</sub> = %3).</p>\n")
             .arg(esc(d_.selectedId()))
             .arg(ref ? ref->candidates.size() : 0)
             .arg(weights(d_.weights.cr.data(), 3));
  out += table(QString("Chosen cutting parameters q* and q** of tool %1 with all cost terms").arg(esc(d_.selectedId())),
               {"Quantity", "Unit", "q*", "q**"}, rows);
  if (ref) {
    QList<QStringList> cands;
    for (std::size_t i = 0; i < ref->candidates.size(); ++i) {
      const RefinementCandidate& c = ref->candidates[i];
      QStringList r{QString::number(i + 1),
                    rpm(c.q.speed_rev_per_s),
                    length(c.q.depth_m),
                    chipLoad(c.q.feed_per_tooth_m),
                    formatCost(c.cost),
                    formatCost(c.time_cost),
                    formatCost(c.frequency_cost),
                    formatCost(c.resultant),
                    formatNumber(c.metrics.settling_time_s * 1e3, 2),
                    formatNumber(c.metrics.overshoot * 100.0, 2)};
      if (i == ref->best) r[0] += " (q**)";
      cands << r;
    }
    out +=
        table("Simulated candidate points (Rule 5), best first by C",
              {"#", "N [rpm]", QString("b [%1]").arg(unit(Quantity::Length)),
               QString("s<sub>t</sub> [%1]").arg(unit(Quantity::ChipLoad)), "C [\u2013]", "C<sub>t</sub> [\u2013]",
               "C<sub>f</sub> [\u2013]", "C<sub>resultant</sub> [\u2013]", "t<sub>s</sub> [ms]", "M<sub>p</sub> [%]"},
              cands);
  }
  out += QString("<p><b>Rule 6 (malfunction loop):</b> %1 iteration(s)%2; c = %3 \u2192 %4.</p>\n")
             .arg(d_.result.malfunction_iterations)
             .arg(d_.result.malfunction_limit_reached ? ", stopped at the iteration limit" : "")
             .arg(weights(d_.weights.c.data(), 3), weights(d_.result.weights.c.data(), 3));
  return out;
}

QString ReportBuilder::figureSection() const {
  QString out = "<h2>4 Figures</h2>\n";
  out +=
      figure(d_.lobe_image,
             QString("Stability lobes of tool %1: nominal (solid) and margined (dashed, \u03b4 = %2 1/s, \u03b1 = %3), "
                     "with q* and q** marked. Spindle speed N in rpm, axial depth b in %4.")
                 .arg(esc(d_.selectedId()))
                 .arg(d_.settings.stability.delta_per_s)
                 .arg(d_.settings.stability.alpha)
                 .arg(unit(Quantity::Length)));
  if (!d_.simulation_image.isEmpty())
    out +=
        figure(d_.simulation_image,
               QString("Time-domain simulation of q** (%1 revolutions from rest): tool displacement x, y in \u00b5m, "
                       "resultant cutting force in %2 and cutting power in %3 against time in ms.")
                   .arg(d_.simulation_revolutions)
                   .arg(unit(Quantity::Force), unit(Quantity::Power)));
  out += figure(d_.sweep_image,
                QString("Minimum tool cost C of every tool against c1 with c2 = 1 \u2212 c1 \u2212 c3 at c3 = %1 "
                        "(figure 4 of Rubio et al. 2006); the dashed line marks the weights used.")
                    .arg(d_.sweep.c3));
  return out;
}

QString ReportBuilder::html() const {
  tables_ = 0;
  figures_ = 0;
  QString out =
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n<title>MillExpert report: " + esc(d_.project.name) +
      "</title>\n<style>\n" + kStyle + "</style></head>\n<body>\n";
  out += "<h1>MillExpert expert report</h1>\n<p><b>" + esc(d_.project.name) +
         "</b><br>Project file: " + esc(d_.project_path) + "</p>\n";
  out += projectSection();  // one by one: the tables and figures are numbered in order
  out += rankingSection();
  out += selectionSection();
  out += figureSection();
  if (flavour_ == ReportFlavour::Browser)
    out += "<p class=\"footer\">" + esc(footer()) + "</p>\n";  // PDF: on every page
  out += "</body></html>\n";
  return out;
}

}  // namespace mx::gui
