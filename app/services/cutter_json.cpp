#include "services/cutter_json.h"

#include <QJsonArray>
#include <numbers>

namespace mx::app {

QJsonObject cutterJson(const MillingSetup& setup) {
  constexpr double kDegPerRad = 180.0 / std::numbers::pi;
  QJsonArray pitch;
  for (int j = 0; j < setup.teeth; ++j)  // the uniform pitch exactly, not through radians
    pitch.append(setup.pitch_rad.empty() ? 360.0 / setup.teeth
                                         : setup.pitch_rad[static_cast<std::size_t>(j)] * kDegPerRad);
  const bool uniform = setup.uniformPitch();
  QJsonObject out{{"teeth", setup.teeth},
                  {"pitch", uniform ? "uniform" : "variable"},
                  {"pitch_deg", pitch},
                  {"helix_deg", setup.helix_rad * kDegPerRad},
                  {"principal_period", uniform ? "tooth" : "revolution"}};
  if (setup.hasRunout()) {
    QJsonArray runout;
    for (int j = 0; j < setup.teeth; ++j) runout.append(setup.runoutM(j) * 1e6);
    out.insert("runout_um", runout);
  }
  return out;
}

}  // namespace mx::app
