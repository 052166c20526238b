// projectFromJson: reads the document into the Project structs (presence and types), then runs
// validateProject (ranges and cross-field rules).
#include <QJsonArray>
#include <QJsonDocument>
#include <initializer_list>

#include "document/json_reader.h"
#include "document/project.h"
#include "document/project_reported_chatter.h"
#include "document/project_sections_io.h"
#include "document/project_validation.h"

namespace mx::app {

namespace {

constexpr const char* kFormat = "millexpert-project";
constexpr int kVersion = 1;

QJsonObject withoutKeys(QJsonObject o, std::initializer_list<const char*> keys) {
  for (const char* k : keys) o.remove(k);
  return o;
}

void readHeader(const ObjectReader& root) {
  if (!root.has("format")) throwMissing("format", QString("string \"%1\"").arg(kFormat));
  const QJsonValue format = root.value("format");
  if (!format.isString()) throwWrongType("format", "a string", format);
  if (format.toString() != kFormat)
    throw ProjectError(
        QString("format = %1: must be \"%2\" (not a MillExpert project)").arg(formatValue(format), kFormat));

  if (!root.has("version")) throwMissing("version", QString("integer %1").arg(kVersion));
  const QJsonValue version = root.value("version");
  if (!version.isDouble()) throwWrongType("version", "a number", version);
  const double v = version.toDouble();
  if (v > kVersion)
    throw ProjectError(QString("version = %1: the file was written by a newer MillExpert; this build reads version %2")
                           .arg(formatNumber(v))
                           .arg(kVersion));
  if (v != kVersion) throw ProjectError(QString("version = %1: must be %2").arg(formatNumber(v)).arg(kVersion));
}

std::vector<SpindleCurveRowSpec> readSpindleCurve(const ObjectReader& machine, const QJsonArray& array) {
  std::vector<SpindleCurveRowSpec> rows;
  for (qsizetype i = 0; i < array.size(); ++i) {
    const ObjectReader r = elementObject(array, i, machine.pathOf("spindle_curve"));
    SpindleCurveRowSpec row;
    row.speed_rpm = r.number("speed_rpm", rules::kNonNegative);
    row.power_W = r.number("power_W", rules::kNonNegative);
    row.unknown = withoutKeys(r.object(), {"speed_rpm", "power_W"});
    rows.push_back(row);
  }
  return rows;
}

MachineSpec readMachine(const ObjectReader& r) {
  MachineSpec m;
  m.name = r.optionalString("name");
  m.spindle_power_W = r.number("spindle_power_W", rules::kPositive);
  m.max_spindle_rpm = r.optionalNumber("max_spindle_rpm");
  m.max_feed_mm_s = r.optionalNumber("max_feed_mm_s");
  m.max_torque_Nm = r.optionalNumber("max_torque_Nm");
  if (auto curve = r.optionalArray("spindle_curve")) m.spindle_curve = readSpindleCurve(r, *curve);
  return m;
}

MaterialSpec readMaterial(const ObjectReader& r) {
  MaterialSpec m;
  m.name = r.string("name");
  m.Kt_N_mm2 = r.number("Kt_N_mm2", rules::kPositive);
  m.Kr = r.number("Kr", rules::kNonNegative);
  m.Kte_N_mm = r.optionalNumber("Kte_N_mm");
  m.Kre_N_mm = r.optionalNumber("Kre_N_mm");
  m.Ka_N_mm2 = r.optionalNumber("Ka_N_mm2");
  m.Kae_N_mm = r.optionalNumber("Kae_N_mm");
  m.process_damping_N_per_m = r.optionalNumber("process_damping_N_per_m");
  m.library = r.optionalString("library");
  return m;
}

OperationSpec readOperation(const ObjectReader& r) {
  OperationSpec op;
  const QString milling = r.string("milling");
  if (milling == "up") {
    op.milling = MillingDirection::Up;
  } else if (milling == "down") {
    op.milling = MillingDirection::Down;
  } else {
    throw ProjectError(
        QString("%1 = %2: must be \"up\" or \"down\"").arg(r.pathOf("milling"), formatValue(r.value("milling"))));
  }
  op.radial_immersion = r.optionalNumber("radial_immersion");
  op.radial_depth_mm = r.optionalNumber("radial_depth_mm");
  op.max_feed_per_tooth_mm = r.number("max_feed_per_tooth_mm", rules::kPositive);
  return op;
}

std::vector<ModeSpec> readModes(const ObjectReader& tool, const QString& key) {
  const QJsonArray array = tool.array(key, "array of modes; [] for a rigid axis");
  std::vector<ModeSpec> modes;
  for (qsizetype i = 0; i < array.size(); ++i) {
    const ObjectReader r = elementObject(array, i, tool.pathOf(key));
    ModeSpec m;
    m.freq_Hz = r.number("freq_Hz", rules::kPositive);
    m.damping_pct = r.number("damping_pct", rules::kPercent);
    m.stiffness_N_per_um = r.number("stiffness_N_per_um", rules::kPositive);
    m.unknown = withoutKeys(r.object(), {"freq_Hz", "damping_pct", "stiffness_N_per_um"});
    modes.push_back(m);
  }
  return modes;
}

// modes_x may be left out when frf_x gives the axis's dynamics.
std::vector<ModeSpec> readAxisModes(const ObjectReader& tool, const QString& key, bool has_frf) {
  if (tool.has(key)) return readModes(tool, key);
  if (has_frf) return {};
  throwMissing(tool.pathOf(key),
               QString("array of modes, [] for a rigid axis; or a tap-test FRF as frf_%1 instead").arg(key.right(1)));
}

std::optional<FrfRefSpec> readFrfRef(const ObjectReader& tool, const QString& key) {
  const std::optional<ObjectReader> r = tool.optionalObject(key);
  if (!r) return std::nullopt;
  FrfRefSpec ref;
  ref.file = r->string("file");
  if (r->has("dataset")) ref.dataset = r->integer("dataset", rules::kCountAtLeastZero);
  ref.quantity = r->optionalString("quantity");
  ref.unknown = withoutKeys(r->object(), {"file", "dataset", "quantity"});
  return ref;
}

std::vector<CuttingPresetSpec> readCuttingData(const ObjectReader& tool) {
  std::vector<CuttingPresetSpec> presets;
  const std::optional<QJsonArray> array = tool.optionalArray("cutting_data");
  if (!array) return presets;
  for (qsizetype i = 0; i < array->size(); ++i) {
    const ObjectReader r = elementObject(*array, i, tool.pathOf("cutting_data"));
    CuttingPresetSpec p;
    p.name = r.string("name");
    p.speed_rpm = r.optionalNumber("speed_rpm");
    p.surface_speed_m_min = r.optionalNumber("surface_speed_m_min");
    p.feed_per_tooth_mm = r.optionalNumber("feed_per_tooth_mm");
    p.feed_mm_min = r.optionalNumber("feed_mm_min");
    p.axial_depth_mm = r.optionalNumber("axial_depth_mm");
    p.radial_depth_mm = r.optionalNumber("radial_depth_mm");
    p.unknown = withoutKeys(r.object(), {"name", "speed_rpm", "surface_speed_m_min", "feed_per_tooth_mm", "feed_mm_min",
                                         "axial_depth_mm", "radial_depth_mm"});
    presets.push_back(p);
  }
  return presets;
}

std::optional<ToolOriginSpec> readOrigin(const ObjectReader& tool) {
  const std::optional<ObjectReader> r = tool.optionalObject("origin");
  if (!r) return std::nullopt;
  ToolOriginSpec origin;
  origin.format = r->string("format");
  const std::optional<ObjectReader> data = r->optionalObject("data");
  if (data) origin.data = data->object();
  return origin;
}

void readCamGeometry(const ObjectReader& r, ToolSpec& t) {
  t.type = r.optionalString("type");
  t.flute_length_mm = r.optionalNumber("flute_length_mm");
  t.overall_length_mm = r.optionalNumber("overall_length_mm");
  t.stickout_mm = r.optionalNumber("stickout_mm");
  t.corner_radius_mm = r.optionalNumber("corner_radius_mm");
  t.cutting_data = readCuttingData(r);
  t.origin = readOrigin(r);
}

ToolSpec readTool(const ObjectReader& r) {
  ToolSpec t;
  t.id = r.string("id");
  t.teeth = r.integer("teeth", rules::kTeeth);
  t.diameter_mm = r.number("diameter_mm", rules::kPositive);
  t.helix_deg = r.number("helix_deg", rules::kHelixDeg);
  t.pitch_deg = r.optionalNumbers("pitch_deg");
  t.runout_um = r.optionalNumbers("runout_um");
  t.Kt_N_mm2 = r.optionalNumber("Kt_N_mm2");
  t.Kr = r.optionalNumber("Kr");
  t.Kte_N_mm = r.optionalNumber("Kte_N_mm");
  t.Kre_N_mm = r.optionalNumber("Kre_N_mm");
  t.Ka_N_mm2 = r.optionalNumber("Ka_N_mm2");
  t.Kae_N_mm = r.optionalNumber("Kae_N_mm");
  t.radial_depth_mm = r.optionalNumber("radial_depth_mm");
  t.max_force_N = r.optionalNumber("max_force_N");
  t.frf_x = readFrfRef(r, "frf_x");
  t.frf_y = readFrfRef(r, "frf_y");
  t.modes_x = readAxisModes(r, "modes_x", t.frf_x.has_value());
  t.modes_y = readAxisModes(r, "modes_y", t.frf_y.has_value());
  readCamGeometry(r, t);
  t.unknown = withoutKeys(r.object(), {"id",
                                       "teeth",
                                       "diameter_mm",
                                       "helix_deg",
                                       "pitch_deg",
                                       "runout_um",
                                       "Kt_N_mm2",
                                       "Kr",
                                       "Kte_N_mm",
                                       "Kre_N_mm",
                                       "Ka_N_mm2",
                                       "Kae_N_mm",
                                       "radial_depth_mm",
                                       "max_force_N",
                                       "modes_x",
                                       "modes_y",
                                       "frf_x",
                                       "frf_y",
                                       "type",
                                       "flute_length_mm",
                                       "overall_length_mm",
                                       "stickout_mm",
                                       "corner_radius_mm",
                                       "cutting_data",
                                       "origin"});
  return t;
}

std::vector<ToolSpec> readTools(const QJsonArray& array) {
  std::vector<ToolSpec> tools;
  for (qsizetype i = 0; i < array.size(); ++i) tools.push_back(readTool(elementObject(array, i, "tools")));
  return tools;
}

ExpertGridSpec readGrid(const ObjectReader& r) {
  ExpertGridSpec g;
  g.speed_from_rpm = r.number("speed_from_rpm", rules::kPositive);
  g.speed_to_rpm = r.number("speed_to_rpm", rules::kPositive);
  g.speed_step_rpm = r.number("speed_step_rpm", rules::kPositive);
  g.depth_divisions = r.integer("depth_divisions", rules::kCountAtLeastOne);
  g.feed_step_mm = r.number("feed_step_mm", rules::kPositive);
  return g;
}

ExpertSpec readExpert(const ObjectReader& r) {
  ExpertSpec e;
  e.delta_per_s = r.number("delta_per_s", rules::kNonNegative);
  e.alpha = r.number("alpha", rules::kFraction);
  if (auto c = r.optionalNumbers("c")) e.c = *c;
  if (auto cr = r.optionalNumbers("cr")) e.cr = *cr;
  if (auto ct = r.optionalNumbers("ct")) e.ct = *ct;
  if (auto cf = r.optionalNumbers("cf")) e.cf = *cf;
  if (auto grid = r.optionalObject("grid")) e.grid = readGrid(*grid);
  readExpertExtras(r, e);
  readReportedChatter(r, e);
  return e;
}

OperatingPointSpec readOperatingPoint(const ObjectReader& r) {
  OperatingPointSpec point;
  point.tool = r.string("tool");
  point.speed_rpm = r.number("speed_rpm", rules::kPointSpeedRpm);
  point.depth_mm = r.number("depth_mm", rules::kPointDepthMm);
  point.feed_mm_per_tooth = r.number("feed_mm_per_tooth", rules::kPointFeedMmPerTooth);
  return point;
}

}  // namespace

Project projectFromJson(const QJsonObject& root) {
  const ObjectReader r(root, QString());
  readHeader(r);
  Project p;
  p.name = r.string("name");
  if (auto machine = r.optionalObject("machine")) p.machine = readMachine(*machine);
  if (auto material = r.optionalObject("material")) p.material = readMaterial(*material);
  if (auto operation = r.optionalObject("operation")) p.operation = readOperation(*operation);
  if (auto tools = r.optionalArray("tools")) p.tools = readTools(*tools);
  if (auto expert = r.optionalObject("expert")) p.expert = readExpert(*expert);
  readProcessSections(r, p);
  if (auto point = r.optionalObject("operating_point")) p.operating_point = readOperatingPoint(*point);
  p.document = unknownKeys(root, projectToJson(p));
  validateProject(p);
  return p;
}

ToolSpec toolFromJson(const QJsonObject& object, const QString& path) {
  return readTool(ObjectReader(object, path));
}

std::vector<ToolSpec> toolsFromJson(const QByteArray& text) {
  QJsonParseError parse{};
  const QJsonDocument doc = QJsonDocument::fromJson(text, &parse);
  if (parse.error != QJsonParseError::NoError)
    throw ProjectError(QString("JSON syntax error at offset %1: %2").arg(parse.offset).arg(parse.errorString()));
  const QJsonValue tools = doc.isArray() ? QJsonValue(doc.array()) : doc.object().value("tools");
  if (tools.isUndefined()) throwMissing("tools", "array of tools");
  if (!tools.isArray()) throwWrongType("tools", "an array", tools);
  std::vector<ToolSpec> out = readTools(tools.toArray());
  validateTools(out, std::nullopt);
  return out;
}

}  // namespace mx::app
