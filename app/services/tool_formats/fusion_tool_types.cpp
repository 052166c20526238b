// Fusion's tool types ("type" of a tool record, as its post-processor API names them: flat end mill,
// ball end mill, ..., drill, tap right hand, probe, holder, turning general). Milling cutters import;
// the rest are not cut by flutes along a milling path, so stability lobes do not apply to them.
#include <QSet>

#include "document/shortened_text.h"
#include "services/tool_formats/fusion_format.h"

namespace mx::app::fusion {

namespace {

const QSet<QString>& millingTypes() {
  static const QSet<QString> types{
      "flat end mill",       "ball end mill", "bull nose end mill",    "chamfer mill",        "face mill",
      "slot mill",           "radius mill",   "dovetail mill",         "tapered mill",        "lollipop mill",
      "form mill",           "thread mill",   "circle segment barrel", "circle segment lens", "circle segment oval",
      "circle segment taper"};
  return types;
}

struct SkippedKind {
  QSet<QString> types;
  const char* reason;
};

const std::vector<SkippedKind>& skippedKinds() {
  static const std::vector<SkippedKind> kinds{
      {{"drill", "center drill", "spot drill", "block drill", "drill block"}, "a drill, not a milling cutter"},
      {{"reamer", "boring bar", "boring head", "counter bore", "counterbore", "counter sink", "countersink"},
       "a hole-finishing tool, not a milling cutter"},
      {{"tap", "tap right hand", "tap left hand", "right hand tap", "left hand tap"}, "a tap, not a milling cutter"},
      {{"probe"}, "a probe, not a cutting tool"},
      {{"holder"}, "a holder without a cutter"},
      {{"engrave"}, "an engraving tool, not a milling cutter"},
      {{"laser cutter", "water jet", "waterjet", "plasma cutter", "wire", "welder", "grinder", "marker"},
       "not a milling cutter"}};
  return kinds;
}

}  // namespace

std::optional<QString> skipReason(const QString& type) {
  const QString name = type.trimmed().toLower();
  if (millingTypes().contains(name)) return std::nullopt;
  if (name.startsWith("turning ")) return QString("%1 (a lathe tool, not a milling cutter)").arg(quoted(type));
  for (const SkippedKind& kind : skippedKinds())
    if (kind.types.contains(name)) return QString("%1 (%2)").arg(quoted(type), kind.reason);
  return QString("type %1 is not a milling cutter this build knows").arg(quoted(type));
}

}  // namespace mx::app::fusion
