// projectToJson: the typed values written over project.document, the unknown keys of every object
// (a typed object the project no longer has is removed with its unknown keys); the elements of
// arrays of objects bring their own.
#include <QJsonArray>

#include "document/project.h"
#include "document/project_reported_chatter.h"
#include "document/project_sections_io.h"

namespace mx::app {

namespace {

// Writes an expert weight vector if the file had it or it differs from the default.
void putWeights(QJsonObject& o, const QString& key, const std::vector<double>& values,
                const std::vector<double>& defaults) {
  if (!o.contains(key) && values == defaults) return;
  o.insert(key, numbersOver(o.value(key).toArray(), values));
}

QJsonArray modesJson(const std::vector<ModeSpec>& modes) {
  QJsonArray out;
  for (const ModeSpec& mode : modes) {
    QJsonObject m = mode.unknown;
    putNumber(m, "freq_Hz", mode.freq_Hz);
    putNumber(m, "damping_pct", mode.damping_pct);
    putNumber(m, "stiffness_N_per_um", mode.stiffness_N_per_um);
    out.append(m);
  }
  return out;
}

QJsonObject frfRefJson(const FrfRefSpec& ref) {
  QJsonObject o = ref.unknown;
  o.insert("file", ref.file);
  if (ref.dataset) o.insert("dataset", *ref.dataset);
  if (ref.quantity) o.insert("quantity", *ref.quantity);
  return o;
}

// An axis with an FRF and no modes keeps its modes key out, as a measured-only axis is written.
void putAxis(QJsonObject& t, const QString& modes_key, const std::vector<ModeSpec>& modes, const QString& frf_key,
             const std::optional<FrfRefSpec>& frf) {
  if (frf) {
    t.insert(frf_key, frfRefJson(*frf));
  } else {
    t.remove(frf_key);
  }
  if (modes.empty() && frf) {
    t.remove(modes_key);
  } else {
    t.insert(modes_key, modesJson(modes));
  }
}

QJsonArray cuttingDataJson(const std::vector<CuttingPresetSpec>& presets) {
  QJsonArray out;
  for (const CuttingPresetSpec& p : presets) {
    QJsonObject o = p.unknown;
    o.insert("name", p.name);
    putOptional(o, "speed_rpm", p.speed_rpm);
    putOptional(o, "surface_speed_m_min", p.surface_speed_m_min);
    putOptional(o, "feed_per_tooth_mm", p.feed_per_tooth_mm);
    putOptional(o, "feed_mm_min", p.feed_mm_min);
    putOptional(o, "axial_depth_mm", p.axial_depth_mm);
    putOptional(o, "radial_depth_mm", p.radial_depth_mm);
    out.append(o);
  }
  return out;
}

void putCamGeometry(QJsonObject& t, const ToolSpec& tool) {
  if (tool.type) {
    t.insert("type", *tool.type);
  } else {
    t.remove("type");
  }
  putOptional(t, "flute_length_mm", tool.flute_length_mm);
  putOptional(t, "overall_length_mm", tool.overall_length_mm);
  putOptional(t, "stickout_mm", tool.stickout_mm);
  putOptional(t, "corner_radius_mm", tool.corner_radius_mm);
  if (tool.cutting_data.empty()) {
    t.remove("cutting_data");
  } else {
    t.insert("cutting_data", cuttingDataJson(tool.cutting_data));
  }
  if (tool.origin) {
    t.insert("origin", QJsonObject{{"format", tool.origin->format}, {"data", tool.origin->data}});
  } else {
    t.remove("origin");
  }
}

QJsonObject toolJson(const ToolSpec& tool) {
  QJsonObject t = tool.unknown;
  t.insert("id", tool.id);
  putNumber(t, "teeth", tool.teeth);
  putNumber(t, "diameter_mm", tool.diameter_mm);
  putNumber(t, "helix_deg", tool.helix_deg);
  putNumbers(t, "pitch_deg", tool.pitch_deg);
  putNumbers(t, "runout_um", tool.runout_um);
  putOptional(t, "Kt_N_mm2", tool.Kt_N_mm2);
  putOptional(t, "Kr", tool.Kr);
  putOptional(t, "Kte_N_mm", tool.Kte_N_mm);
  putOptional(t, "Kre_N_mm", tool.Kre_N_mm);
  putOptional(t, "Ka_N_mm2", tool.Ka_N_mm2);
  putOptional(t, "Kae_N_mm", tool.Kae_N_mm);
  putOptional(t, "radial_depth_mm", tool.radial_depth_mm);
  putOptional(t, "max_force_N", tool.max_force_N);
  putAxis(t, "modes_x", tool.modes_x, "frf_x", tool.frf_x);
  putAxis(t, "modes_y", tool.modes_y, "frf_y", tool.frf_y);
  putCamGeometry(t, tool);
  return t;
}

QJsonArray spindleCurveJson(const std::vector<SpindleCurveRowSpec>& rows) {
  QJsonArray out;
  for (const SpindleCurveRowSpec& row : rows) {
    QJsonObject r = row.unknown;
    putNumber(r, "speed_rpm", row.speed_rpm);
    putNumber(r, "power_W", row.power_W);
    out.append(r);
  }
  return out;
}

QJsonObject machineJson(QJsonObject o, const MachineSpec& m) {
  if (m.name) {
    o.insert("name", *m.name);
  } else {
    o.remove("name");
  }
  putNumber(o, "spindle_power_W", m.spindle_power_W);
  putOptional(o, "max_spindle_rpm", m.max_spindle_rpm);
  putOptional(o, "max_feed_mm_s", m.max_feed_mm_s);
  putOptional(o, "max_torque_Nm", m.max_torque_Nm);
  if (m.spindle_curve) {
    o.insert("spindle_curve", spindleCurveJson(*m.spindle_curve));
  } else {
    o.remove("spindle_curve");
  }
  return o;
}

QJsonObject materialJson(QJsonObject o, const MaterialSpec& m) {
  o.insert("name", m.name);
  putNumber(o, "Kt_N_mm2", m.Kt_N_mm2);
  putNumber(o, "Kr", m.Kr);
  putOptional(o, "Kte_N_mm", m.Kte_N_mm);
  putOptional(o, "Kre_N_mm", m.Kre_N_mm);
  putOptional(o, "Ka_N_mm2", m.Ka_N_mm2);
  putOptional(o, "Kae_N_mm", m.Kae_N_mm);
  putOptional(o, "process_damping_N_per_m", m.process_damping_N_per_m);
  if (m.library) {
    o.insert("library", *m.library);
  } else {
    o.remove("library");
  }
  return o;
}

QJsonObject operationJson(QJsonObject o, const OperationSpec& op) {
  o.insert("milling", op.milling == MillingDirection::Up ? "up" : "down");
  putOptional(o, "radial_immersion", op.radial_immersion);
  putOptional(o, "radial_depth_mm", op.radial_depth_mm);
  putNumber(o, "max_feed_per_tooth_mm", op.max_feed_per_tooth_mm);
  return o;
}

QJsonObject gridJson(QJsonObject o, const ExpertGridSpec& g) {
  putNumber(o, "speed_from_rpm", g.speed_from_rpm);
  putNumber(o, "speed_to_rpm", g.speed_to_rpm);
  putNumber(o, "speed_step_rpm", g.speed_step_rpm);
  putNumber(o, "depth_divisions", g.depth_divisions);
  putNumber(o, "feed_step_mm", g.feed_step_mm);
  return o;
}

QJsonObject expertJson(QJsonObject o, const ExpertSpec& e) {
  const ExpertSpec defaults;
  putNumber(o, "delta_per_s", e.delta_per_s);
  putNumber(o, "alpha", e.alpha);
  putWeights(o, "c", e.c, defaults.c);
  putWeights(o, "cr", e.cr, defaults.cr);
  putWeights(o, "ct", e.ct, defaults.ct);
  putWeights(o, "cf", e.cf, defaults.cf);
  if (e.grid) {
    o.insert("grid", gridJson(o.value("grid").toObject(), *e.grid));
  } else {
    o.remove("grid");
  }
  putExpertExtras(o, e);
  putReportedChatter(o, e);
  return o;
}

QJsonObject operatingPointJson(QJsonObject o, const OperatingPointSpec& point) {
  o.insert("tool", point.tool);
  putNumber(o, "speed_rpm", point.speed_rpm);
  putNumber(o, "depth_mm", point.depth_mm);
  putNumber(o, "feed_mm_per_tooth", point.feed_mm_per_tooth);
  return o;
}

template <typename Spec, typename Writer>
void putSection(QJsonObject& root, const QString& key, const std::optional<Spec>& spec, Writer write) {
  if (spec) {
    root.insert(key, write(root.value(key).toObject(), *spec));
  } else {
    root.remove(key);
  }
}

}  // namespace

QJsonObject toolToJson(const ToolSpec& tool) {
  return toolJson(tool);
}

QJsonObject projectToJson(const Project& project) {
  QJsonObject root = project.document;
  root.insert("format", "millexpert-project");
  putNumber(root, "version", 1);
  root.insert("name", project.name);
  putSection(root, "machine", project.machine, machineJson);
  putSection(root, "material", project.material, materialJson);
  putSection(root, "operation", project.operation, operationJson);
  if (!project.tools.empty() || root.contains("tools")) {
    QJsonArray tools;
    for (const ToolSpec& tool : project.tools) tools.append(toolJson(tool));
    root.insert("tools", tools);
  }
  putSection(root, "expert", project.expert, expertJson);
  putProcessSections(root, project);
  putSection(root, "operating_point", project.operating_point, operatingPointJson);
  return root;
}

}  // namespace mx::app
