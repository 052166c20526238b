// Fuzz target of the Grafcet charts of a project (docs/grafcet.md): one chart's JSON bytes through
// grafcetChartFromJson (structure, a ProjectError naming the JSON path), grafcetChartErrors (content),
// then the interpreter for a bounded number of scans. The promises: a chart that loads writes back
// (grafcetChartToJson) to the same chart; a chart without errors builds an interpreter, which runs
// the same by signal name and on its fast path (bindSignals, scanValues), reports only steps of the
// chart, and always has an active step.
#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "core/invalid_input.h"
#include "document/project.h"
#include "document/project_grafcet_io.h"
#include "fuzz_check.h"
#include "grafcet/grafcet_interpreter.h"

namespace {

using mx::fuzz::require;

constexpr int kScans = 32;

void checkRoundTrip(const mx::app::GrafcetChartSpec& spec) {
  const QJsonObject written = mx::app::grafcetChartToJson(spec);
  try {
    const mx::app::GrafcetChartSpec again = mx::app::grafcetChartFromJson(written, "chart");
    require(again == spec, "a chart writes back to the same chart");
    require(mx::app::grafcetChartToJson(again) == written, "a chart writes the same JSON again");
  } catch (const mx::app::ProjectError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise("a written chart loads again");
  }
}

bool sameScan(const mx::ScanOutput& a, const mx::ScanOutput& b) {
  return a.active_steps == b.active_steps && a.level_actions == b.level_actions &&
         a.impulse_actions == b.impulse_actions && a.stable == b.stable && a.iterations == b.iterations;
}

void checkRun(const mx::GrafcetChart& chart, mx::fuzz::InputNumbers& numbers) {
  std::set<std::string> stepNames;
  for (const mx::GrafcetStep& s : chart.steps) stepNames.insert(s.name);
  mx::GrafcetInterpreter byName(chart);
  mx::GrafcetInterpreter fast(chart);
  // The fast path's order: the chart's signals backwards, and one it does not read.
  std::vector<std::string> order(byName.signalNames().rbegin(), byName.signalNames().rend());
  order.emplace_back("fuzz_unread_signal");
  fast.bindSignals(order);
  for (int scan = 0; scan < kScans; ++scan) {
    mx::SignalValues values;
    std::vector<double> cells;
    for (const std::string& name : order) {
      cells.push_back(static_cast<double>(numbers.next() % 2));
      values[name] = cells.back();
    }
    const mx::ScanOutput out = byName.scan(values);
    require(sameScan(out, fast.scanValues(cells)), "a scan by name and on the fast path agree");
    require(!out.active_steps.empty(), "a chart always has an active step");
    for (const std::string& step : out.active_steps) require(stepNames.count(step) != 0, "active steps are steps");
    require(out.iterations >= 0 && out.iterations <= byName.settings().iteration_limit,
            "a scan stays within the iteration limit");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const QJsonDocument document =
      QJsonDocument::fromJson(QByteArray(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size)));
  if (document.isNull()) return 0;
  mx::app::GrafcetChartSpec spec;
  try {
    spec = mx::app::grafcetChartFromJson(
        document.isObject() ? QJsonValue(document.object()) : QJsonValue(document.array()), "chart");
  } catch (const mx::app::ProjectError&) {
    return 0;
  }
  checkRoundTrip(spec);
  if (!mx::app::grafcetChartErrors(spec.chart, "chart").isEmpty()) return 0;
  mx::fuzz::InputNumbers numbers(mx::fuzz::bytesOf(data, size));
  try {
    checkRun(spec.chart, numbers);
  } catch (const mx::InvalidInput& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise("a chart without errors runs");
  }
  return 0;
}
