#include "stability_model_text.h"

#include <QObject>
#include <QStringList>
#include <numbers>

#include "stability/zoa_validity.h"

namespace mx::widgets {

namespace {

QString helixText(const MillingSetup& setup) {
  return QObject::tr("%1\u00b0 helix").arg(setup.helix_rad * 180.0 / std::numbers::pi, 0, 'g', 3);
}

}  // namespace

QString modelLabel(StabilityMethod method, const MillingSetup& setup) {
  QStringList parts{method == StabilityMethod::ZeroOrder ? QStringLiteral("ZOA") : QStringLiteral("SDM"),
                    setup.teeth == 1 ? QObject::tr("1 tooth") : QObject::tr("%1 teeth").arg(setup.teeth),
                    setup.uniformPitch() ? QObject::tr("uniform pitch") : QObject::tr("variable pitch")};
  if (setup.helix_rad != 0.0) parts << helixText(setup);
  return parts.join(", ");
}

QString methodAdvice(StabilityMethod method, const MillingSetup& setup) {
  if (method != StabilityMethod::ZeroOrder) return {};
  QStringList reasons;
  if (!setup.uniformPitch()) reasons << QObject::tr("variable pitch");
  if (setup.helix_rad != 0.0) reasons << helixText(setup);
  const ZoaValidity validity = zoaValidity(setup);
  if (setup.uniformPitch() && !validity.accurate)
    reasons << QObject::tr("intermittent cut: a/D = %1 < %2")
                   .arg(validity.radial_immersion, 0, 'g', 3)
                   .arg(validity.min_radial_immersion, 0, 'g', 3);
  if (setup.process_damping_n_per_m > 0.0)
    reasons << QObject::tr("process damping C_i = %1 N/m left out").arg(setup.process_damping_n_per_m, 0, 'g', 3);
  if (reasons.isEmpty()) return {};
  return QObject::tr("ZOA: approximate for this tool (%1); SDM models pitch, helix and process damping")
      .arg(reasons.join(", "));
}

}  // namespace mx::widgets
