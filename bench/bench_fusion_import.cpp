// Fusion 360 tool library import (readFusionLibrary): a generated library of milling cutters in the
// shape of a shop's export (geometry, a holder of three segments, post-process data, expressions, two
// cutting presets each; every fourth tool in inches), read from the JSON form and from a `.tools`
// archive, and the export of the imported tools. Target: 5 000 tools import in 1 s or less.
#include <benchmark/benchmark.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "services/tool_formats/fusion_library.h"

namespace {

QJsonObject preset(const QString& name, double rpm, double chip_load, int teeth) {
  return {{"name", name},
          {"guid", QString("preset-%1-%2").arg(name).arg(rpm)},
          {"n", rpm},
          {"f_z", chip_load},
          {"v_f", rpm * chip_load * teeth},
          {"v_f_plunge", rpm * chip_load},
          {"stepdown", 0},
          {"stepover", 0},
          {"use-stepdown", false},
          {"tool-coolant", "flood"}};
}

QJsonObject tool(int index) {
  const bool inches = index % 4 == 3;
  const double scale = inches ? 1.0 / 25.4 : 1.0;
  const double diameter = (2.0 + index % 24) * scale;
  const int teeth = 2 + index % 5;
  const QJsonArray segments{QJsonObject{{"height", 4}, {"lower-diameter", 40}, {"upper-diameter", 50}},
                            QJsonObject{{"height", 26}, {"lower-diameter", 50}, {"upper-diameter", 50}},
                            QJsonObject{{"height", 40}, {"lower-diameter", 42}, {"upper-diameter", 42}}};
  return {{"BMC", "carbide"},
          {"description", QString("bench cutter %1").arg(index)},
          {"expressions", QJsonObject{{"tool_diameter", QString("%1 %2").arg(diameter).arg(inches ? "in" : "mm")}}},
          {"geometry", QJsonObject{{"DC", diameter},
                                   {"NOF", teeth},
                                   {"LCF", 3.0 * diameter},
                                   {"LB", 4.0 * diameter},
                                   {"OAL", 8.0 * diameter + 40.0 * scale},
                                   {"RE", index % 3 == 0 ? diameter / 2.0 : 0.0},
                                   {"SFDM", diameter},
                                   {"HAND", true}}},
          {"guid", QString("bench-guid-%1").arg(index)},
          {"holder", QJsonObject{{"description", "BT40 ER32"}, {"segments", segments}, {"type", "holder"}}},
          {"post-process", QJsonObject{{"number", index + 1}, {"diameter-offset", index + 1}, {"live", true}}},
          {"product-id", QString("EM-%1").arg(index)},
          {"start-values", QJsonObject{{"presets", QJsonArray{preset("Aluminium", 12000, 0.05 * scale, teeth),
                                                              preset("Steel", 4000, 0.03 * scale, teeth)}}}},
          {"type", index % 3 == 0 ? "ball end mill" : "flat end mill"},
          {"unit", inches ? "inches" : "millimeters"},
          {"vendor", "Bench"}};
}

QByteArray library(int count) {
  QJsonArray data;
  for (int i = 0; i < count; ++i) data.append(tool(i));
  return QJsonDocument(QJsonObject{{"data", data}}).toJson(QJsonDocument::Indented);
}

void BM_ReadFusionJson(benchmark::State& state) {
  const QByteArray bytes = library(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(mx::app::readFusionLibrary(bytes, "bench.json").tools.size());
  state.counters["MB"] = static_cast<double>(bytes.size()) / 1e6;
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ReadFusionJson)->Arg(5000)->Unit(benchmark::kMillisecond);

void BM_ReadFusionTools(benchmark::State& state) {
  const auto tools = mx::app::readFusionLibrary(library(static_cast<int>(state.range(0))), "bench.json").tools;
  const QByteArray zipped = mx::app::writeFusionLibrary(tools, mx::app::FusionContainer::Zipped);
  for (auto _ : state) benchmark::DoNotOptimize(mx::app::readFusionLibrary(zipped, "bench.tools").tools.size());
  state.counters["MB"] = static_cast<double>(zipped.size()) / 1e6;
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ReadFusionTools)->Arg(5000)->Unit(benchmark::kMillisecond);

void BM_WriteFusionJson(benchmark::State& state) {
  const auto tools = mx::app::readFusionLibrary(library(static_cast<int>(state.range(0))), "bench.json").tools;
  for (auto _ : state)
    benchmark::DoNotOptimize(mx::app::writeFusionLibrary(tools, mx::app::FusionContainer::Json).size());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_WriteFusionJson)->Arg(5000)->Unit(benchmark::kMillisecond);

}  // namespace
