#include "e2e_readouts.h"

#include <QJsonArray>
#include <cmath>
#include <limits>

namespace mx::e2e {

namespace {

// Same code on the same lobes: only rounding may differ.
constexpr double kSameCode = 1e-9;

double jsonNumber(const QJsonObject& o, const QString& key) {
  const QJsonValue v = o.value(key);
  return v.isDouble() ? v.toDouble() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

void compareReadouts(Report& report, const QString& prefix, const widgets::PointReadout& a,
                     const widgets::PointReadout& e) {
  report.check(prefix + ".tool", a.tool_id == e.tool_id, QString("'%1' vs '%2'").arg(a.tool_id, e.tool_id));
  report.check(
      prefix + ".valid", a.valid == e.valid && a.stable == e.stable,
      QString("valid %1 stable %2 vs valid %3 stable %4").arg(a.valid).arg(a.stable).arg(e.valid).arg(e.stable));
  const struct {
    const char* name;
    double actual, expected;
  } values[] = {{"speed_rpm", a.speed_rpm, e.speed_rpm},
                {"depth_mm", a.depth_mm, e.depth_mm},
                {"feed_mm_per_tooth", a.feed_mm_per_tooth, e.feed_mm_per_tooth},
                {"peak_power_W", a.peak_power_w, e.peak_power_w},
                {"power_limit_W", a.power_limit_w, e.power_limit_w},
                {"MRR_mm3_s", a.mrr_mm3_per_s, e.mrr_mm3_per_s},
                {"peak_force_N", a.peak_force_n, e.peak_force_n},
                {"force_limit_N", a.force_limit_n, e.force_limit_n},
                {"blim_mm", a.blim_mm, e.blim_mm},
                {"delta_Ns_rpm", a.delta_ns_rpm, e.delta_ns_rpm},
                {"ROS", a.ros, e.ros}};
  for (const auto& v : values) report.near(prefix + "." + v.name, v.actual, v.expected, 1e-12, kSameCode);
}

ShownNumber shownNumber(const QString& text) {
  ShownNumber n;
  const QString first = text.section(' ', 0, 0);
  n.value = first.toDouble(&n.ok);
  const qsizetype dot = first.indexOf('.');
  const int decimals = dot < 0 ? 0 : static_cast<int>(first.size() - dot - 1);
  n.half_unit = 0.5 * std::pow(10.0, -decimals);
  return n;
}

void compareWithCliPoint(Report& report, const widgets::PointReadout& r, const QHash<QString, QString>& shown,
                         const QJsonObject& cli) {
  report.check("cli.point.tool", r.tool_id == cli.value("tool").toString(),
               QString("GUI '%1', CLI '%2'").arg(r.tool_id, cli.value("tool").toString()));
  report.check("cli.point.stable", r.valid && r.stable == cli.value("stable").toBool(),
               QString("GUI %1, CLI %2")
                   .arg(r.stable ? "stable" : "unstable", cli.value("stable").toBool() ? "stable" : "unstable"));
  const double blim =
      cli.value("blim_mm").isNull() ? std::numeric_limits<double>::infinity() : jsonNumber(cli, "blim_mm");
  const double ros = cli.value("ROS").isNull() ? std::numeric_limits<double>::quiet_NaN() : jsonNumber(cli, "ROS");
  // Both evaluate the same engine on the same 10 rpm lobe grid; power, force and MRR are closed forms.
  report.near("cli.point.speed_rpm", r.speed_rpm, jsonNumber(cli, "speed_rpm"), 0.0, kSameCode, "rpm");
  report.near("cli.point.depth_mm", r.depth_mm, jsonNumber(cli, "depth_mm"), 0.0, kSameCode, "mm");
  report.near("cli.point.blim_mm", r.blim_mm, blim, 1e-9, 1e-6, "mm");
  report.near("cli.point.delta_Ns_rpm", r.delta_ns_rpm, jsonNumber(cli, "delta_Ns_rpm"), 1e-6, 1e-6, "rpm");
  report.near("cli.point.ROS", r.ros, ros, 1e-9, 1e-6);
  report.near("cli.point.peak_power_W", r.peak_power_w, jsonNumber(cli, "peak_power_W"), 0.0, kSameCode, "W");
  report.near("cli.point.MRR_mm3_s", r.mrr_mm3_per_s, jsonNumber(cli, "MRR_mm3_s"), 0.0, kSameCode, "mm3/s");
  report.near("cli.point.peak_force_N", r.peak_force_n, jsonNumber(cli, "peak_force_N"), 0.0, kSameCode, "N");
  if (cli.contains("available_power_W")) {
    report.near("cli.point.available_power_W", r.power_limit_w, jsonNumber(cli, "available_power_W"), 0.0, kSameCode,
                "W");
    report.check("cli.point.power_ok", r.powerOk() == cli.value("power_ok").toBool(),
                 QString("GUI %1, CLI %2").arg(r.powerOk()).arg(cli.value("power_ok").toBool()));
  }
  const bool force_ok = !cli.contains("force_ok") || cli.value("force_ok").toBool();
  report.check("cli.point.force_ok", r.forceOk() == force_ok, QString("GUI %1, CLI %2").arg(r.forceOk()).arg(force_ok));

  // The verdict the panel shows, from the CLI's stability ("verdict" adds the marginal band) and limits.
  const QString verdict = shown.value("verdict");
  const QString stability = cli.contains("verdict")        ? cli.value("verdict").toString()
                            : cli.value("stable").toBool() ? "stable"
                                                           : "unstable";
  const bool power_ok = !cli.contains("power_ok") || cli.value("power_ok").toBool();
  bool verdict_ok = false;
  if (stability == "unstable")
    verdict_ok = verdict.startsWith("UNSTABLE");
  else if (stability == "marginal")
    verdict_ok = verdict.startsWith("MARGINAL");
  else if (!power_ok)
    verdict_ok = verdict.contains("power exceeded");
  else if (!force_ok)
    verdict_ok = verdict.contains("force limit exceeded");
  else
    verdict_ok = verdict == "STABLE";
  report.check(
      "cli.point.verdict_text", verdict_ok,
      QString("panel '%1' for CLI %2, power_ok=%3, force_ok=%4").arg(verdict, stability).arg(power_ok).arg(force_ok));

  // The panel's rounded texts: within half a unit of their last digit of the CLI's numbers.
  const struct {
    const char* field;
    double cli;
  } texts[] = {{"speed", jsonNumber(cli, "speed_rpm")},
               {"depth", jsonNumber(cli, "depth_mm")},
               {"feed", jsonNumber(cli, "feed_per_tooth_mm")},
               {"power", jsonNumber(cli, "peak_power_W")},
               {"force", jsonNumber(cli, "peak_force_N")},
               {"mrr", jsonNumber(cli, "MRR_mm3_s") * 0.06},  // shown in cm^3/min (metric shop units)
               {"blim", blim},
               {"dns", jsonNumber(cli, "delta_Ns_rpm")},
               {"ros", ros},
               {"power_fraction", 100.0 * jsonNumber(cli, "power_fraction")}};
  for (const auto& t : texts) {
    if (!std::isfinite(t.cli)) continue;  // "—" or "none below the cap": compared as numbers above
    const QString name = QString("cli.point.text.%1").arg(t.field);
    const ShownNumber n = shownNumber(shown.value(t.field));
    if (!n.ok)
      report.check(name, false, QString("the panel shows '%1', not a number").arg(shown.value(t.field)));
    else
      report.near(name, n.value, t.cli, n.half_unit * (1.0 + 1e-9), 1e-9);
  }
}

void compareWithCliRanking(Report& report, const QString& prefix, const QVector<widgets::RankingRow>& rows,
                           const QString& selected, const QJsonObject& cli) {
  const QJsonArray ranking = cli.value("ranking").toArray();
  report.check(prefix + ".selected", selected == cli.value("selected").toString(),
               QString("GUI '%1', CLI '%2'").arg(selected, cli.value("selected").toString()));
  if (!report.check(prefix + ".rows", rows.size() == ranking.size(),
                    QString("GUI %1 rows, CLI %2").arg(rows.size()).arg(ranking.size())))
    return;
  for (qsizetype i = 0; i < rows.size(); ++i) {
    const widgets::RankingRow& row = rows[i];
    const QJsonObject c = ranking[i].toObject();
    const QJsonObject q = c.value("q").toObject();
    const QString at = QString("%1[%2]").arg(prefix).arg(i + 1);
    report.check(at + ".tool", row.tool == c.value("tool").toString(),
                 QString("GUI '%1', CLI '%2'").arg(row.tool, c.value("tool").toString()));
    report.near(at + ".min_cost", row.min_cost, jsonNumber(c, "min_cost"), 1e-12, 1e-6);
    report.near(at + ".q_speed_rpm", row.speed_rpm, jsonNumber(q, "speed_rpm"), 1e-6, 1e-9, "rpm");
    report.near(at + ".q_depth_mm", row.depth_mm, jsonNumber(q, "depth_mm"), 1e-9, 1e-6, "mm");
    report.near(at + ".q_feed_mm", row.feed_mm_per_tooth, jsonNumber(q, "feed_mm_per_tooth"), 1e-9, 1e-9, "mm");
    report.near(at + ".power_W", row.power_w, jsonNumber(c, "power_W"), 1e-9, 1e-6, "W");
  }
}

void compareRankings(Report& report, const QString& prefix, const QVector<widgets::RankingRow>& actual,
                     const QVector<widgets::RankingRow>& expected) {
  if (!report.check(prefix + ".rows", actual.size() == expected.size(),
                    QString("%1 rows, expected %2").arg(actual.size()).arg(expected.size())))
    return;
  for (qsizetype i = 0; i < actual.size(); ++i) {
    const QString at = QString("%1[%2]").arg(prefix).arg(i + 1);
    report.check(at + ".tool", actual[i].tool == expected[i].tool,
                 QString("'%1', expected '%2'").arg(actual[i].tool, expected[i].tool));
    report.near(at + ".min_cost", actual[i].min_cost, expected[i].min_cost, 1e-12, kSameCode);
    report.near(at + ".q_speed_rpm", actual[i].speed_rpm, expected[i].speed_rpm, 1e-9, kSameCode, "rpm");
    report.near(at + ".q_depth_mm", actual[i].depth_mm, expected[i].depth_mm, 1e-12, kSameCode, "mm");
  }
}

}  // namespace mx::e2e
