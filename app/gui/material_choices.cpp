#include "material_choices.h"

#include <QStringList>
#include <QtDebug>

#include "document/project_rules.h"
#include "services/service_errors.h"

namespace mx::gui {

namespace {

struct ShownValue {
  const char* key;  // in the library and its sources
  const char* symbol;
  const char* unit;
  std::optional<double> value;
};

std::vector<ShownValue> shownValues(const app::MaterialEntry& e) {
  return {{"Kt_N_mm2", "K_t", " N/mm²", e.Kt_N_mm2},
          {"Kr", "K_r", "", e.Kr},
          {"Kte_N_mm", "K_te", " N/mm", e.Kte_N_mm},
          {"Kre_N_mm", "K_re", " N/mm", e.Kre_N_mm},
          {"Ka_N_mm2", "K_a", " N/mm²", e.Ka_N_mm2},
          {"Kae_N_mm", "K_ae", " N/mm", e.Kae_N_mm},
          {"process_damping_N_per_m", "C_i", " N/m", e.process_damping_N_per_m}};
}

// How far a value's source goes (docs/materials-sources.md): a note means it was not checked, and
// conditions that start "DERIVED" mean it was computed from checked values.
QString sourceKind(const app::MaterialSource& s) {
  if (s.note) return QObject::tr("typical, source not checked");
  if (s.conditions && s.conditions->startsWith("DERIVED")) return QObject::tr("derived");
  return s.cite ? QObject::tr("cited") : QObject::tr("no source given");
}

QString tooltipOf(const app::MaterialEntry& e) {
  QStringList values;
  QMap<QString, QStringList> byKind;
  for (const ShownValue& v : shownValues(e)) {
    if (!v.value) continue;
    values << QString("%1 %2%3").arg(v.symbol, app::formatNumber(*v.value), v.unit);
    byKind[sourceKind(e.sources.value(v.key))] << v.symbol;
  }
  QStringList lines{QObject::tr("%1, ISO group %2").arg(e.id, e.iso_group), values.join(", ")};
  for (auto it = byKind.begin(); it != byKind.end(); ++it) lines << QString("%1: %2").arg(it.key(), it->join(", "));
  lines << QObject::tr("Sources: docs/materials-sources.md");
  return lines.join('\n');
}

}  // namespace

QList<widgets::MaterialChoice> materialChoices(const std::vector<app::MaterialEntry>& library) {
  QList<widgets::MaterialChoice> choices;
  for (const app::MaterialEntry& e : library) choices.append({e.iso_group, tooltipOf(e), app::materialSpecOf(e)});
  return choices;
}

QList<widgets::MaterialChoice> bundledMaterialChoices() {
  try {
    return materialChoices(app::bundledMaterialLibrary());
  } catch (const app::InputError& e) {
    qWarning("materials library: %s", e.what());
    return {};
  }
}

}  // namespace mx::gui
