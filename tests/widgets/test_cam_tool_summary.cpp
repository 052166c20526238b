// The line under the tool library on a tool's CAM data: each field with its unit (mm or inch), the
// presets in full as a tooltip, nothing for a tool without CAM data.
#include "cam_tool_summary.h"
#include "test_registry.h"

using mx::app::ToolSpec;
using mx::widgets::DisplayUnits;

namespace {

ToolSpec camTool() {
  ToolSpec t;
  t.id = "T7";
  t.teeth = 3;
  t.diameter_mm = 12.7;
  t.type = "bull nose end mill";
  t.flute_length_mm = 25.4;
  t.overall_length_mm = 76.2;
  t.stickout_mm = 38.1;
  t.corner_radius_mm = 0.508;
  mx::app::CuttingPresetSpec preset;
  preset.name = "Aluminium";
  preset.speed_rpm = 12000;
  preset.surface_speed_m_min = 478.8;
  preset.feed_per_tooth_mm = 0.08;
  preset.axial_depth_mm = 6.35;
  t.cutting_data = {preset};
  t.origin = mx::app::ToolOriginSpec{"fusion", {}};
  return t;
}

}  // namespace

class TestCamToolSummary : public QObject {
  Q_OBJECT
 private slots:
  void metric() {
    QCOMPARE(mx::widgets::camToolSummary(camTool(), nullptr),
             QString("bull nose end mill · flute length 25.4 mm · overall 76.2 mm · stickout 38.1 mm · corner radius "
                     "0.508 mm · 1 cutting preset · from Fusion 360"));
    QCOMPARE(mx::widgets::cuttingPresetsText(camTool(), nullptr),
             QString("Aluminium: 12000 rpm, 478.8 m/min, 0.08 mm/tooth, ap 6.35 mm"));
  }

  void inch() {
    DisplayUnits units;
    units.setLength(DisplayUnits::Length::Inch);
    QCOMPARE(
        mx::widgets::camToolSummary(camTool(), &units),
        QString("bull nose end mill · flute length 1 in · overall 3 in · stickout 1.5 in · corner radius 0.02 in · "
                "1 cutting preset · from Fusion 360"));
    QCOMPARE(mx::widgets::cuttingPresetsText(camTool(), &units),
             QString("Aluminium: 12000 rpm, 478.8 m/min, 0.08 mm/tooth, ap 0.25 in"));
  }

  void noCamData() {
    ToolSpec plain;
    plain.id = "R1";
    plain.teeth = 2;
    plain.diameter_mm = 10;
    QCOMPARE(mx::widgets::camToolSummary(plain, nullptr), QString());
    QCOMPARE(mx::widgets::cuttingPresetsText(plain, nullptr), QString());
  }
};

MX_REGISTER_TEST(TestCamToolSummary)
#include "test_cam_tool_summary.moc"
