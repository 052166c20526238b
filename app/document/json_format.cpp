#include "document/json_format.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QStringList>
#include <algorithm>

namespace mx::app {

namespace {

constexpr qsizetype kLineWidth = 110;

// Documented key order, shared by all levels (no key name has two conflicting positions).
const QStringList& keyOrder() {
  static const QStringList order{"format",
                                 "version",
                                 "name",
                                 "description",  // root
                                 "machine",
                                 "material",
                                 "operation",
                                 "tools",
                                 "expert",
                                 "operating_point",  // sections
                                 "spindle_power_W",
                                 "max_spindle_rpm",
                                 "max_feed_mm_s",
                                 "max_torque_Nm",
                                 "spindle_curve",  // machine
                                 "milling",
                                 "radial_immersion",
                                 "radial_depth_mm",
                                 "max_feed_per_tooth_mm",  // operation
                                 "id",
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
                                 "process_damping_N_per_m",
                                 "library",  // material
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
                                 "origin",  // tool
                                 "surface_speed_m_min",
                                 "feed_per_tooth_mm",
                                 "feed_mm_min",
                                 "axial_depth_mm",  // cutting preset
                                 "file",
                                 "dataset",
                                 "quantity",  // FRF reference
                                 "freq_Hz",
                                 "damping_pct",
                                 "stiffness_N_per_um",  // mode
                                 "delta_per_s",
                                 "alpha",
                                 "c",
                                 "cr",
                                 "ct",
                                 "cf",
                                 "grid",
                                 "max_malfunction_iterations",
                                 "reported_chatter",  // expert
                                 "tool",
                                 "speed_rpm",
                                 "depth_mm",           // reported chatter
                                 "feed_mm_per_tooth",  // operating point
                                 "speed_from_rpm",
                                 "speed_to_rpm",
                                 "speed_step_rpm",
                                 "depth_divisions",
                                 "feed_step_mm"};
  return order;
}

QStringList orderedKeys(const QJsonObject& o) {
  QStringList keys = o.keys();  // alphabetical
  const QStringList& order = keyOrder();
  auto rank = [&order](const QString& k) {
    const qsizetype r = order.indexOf(k);
    return r < 0 ? order.size() : r;
  };
  std::stable_sort(keys.begin(), keys.end(), [&](const QString& a, const QString& b) { return rank(a) < rank(b); });
  return keys;
}

QByteArray scalar(const QJsonValue& v) {
  const QByteArray wrapped = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
  return wrapped.mid(1, wrapped.size() - 2);
}

QByteArray inlineText(const QJsonValue& v) {
  if (v.isObject()) {
    const QJsonObject o = v.toObject();
    if (o.isEmpty()) return "{}";
    QByteArrayList parts;
    for (const QString& k : orderedKeys(o)) parts << scalar(k) + ": " + inlineText(o.value(k));
    return "{ " + parts.join(", ") + " }";
  }
  if (v.isArray()) {
    QByteArrayList parts;
    for (const auto& e : v.toArray()) parts << inlineText(e);
    return "[" + parts.join(", ") + "]";
  }
  return scalar(v);
}

void write(QByteArray& out, const QJsonValue& v, int indent, qsizetype column, bool forceBlock) {
  const QByteArray flat = inlineText(v);
  if ((!v.isObject() && !v.isArray()) || (!forceBlock && column + flat.size() <= kLineWidth)) {
    out += flat;
    return;
  }
  const QByteArray inner(indent + 2, ' ');
  QByteArrayList lines;
  if (v.isObject()) {
    const QJsonObject o = v.toObject();
    for (const QString& k : orderedKeys(o)) {
      QByteArray line = inner + scalar(k) + ": ";
      write(line, o.value(k), indent + 2, line.size(), false);
      lines << line;
    }
  } else {
    for (const auto& e : v.toArray()) {
      QByteArray line = inner;
      write(line, e, indent + 2, line.size(), false);
      lines << line;
    }
  }
  const char open = v.isObject() ? '{' : '[';
  const char close = v.isObject() ? '}' : ']';
  out += open;
  out += '\n';
  out += lines.join(",\n");
  out += '\n' + QByteArray(indent, ' ') + close;
}

}  // namespace

QByteArray formatProjectJson(const QJsonObject& root) {
  QByteArray out;
  write(out, root, 0, 0, true);
  out += '\n';
  return out;
}

}  // namespace mx::app
