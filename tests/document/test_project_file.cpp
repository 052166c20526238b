// Project document (.mxproj): parsing, SI conversion of setupFor, the validation rules, and
// round-trip saving that keeps unknown keys.
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "document/project.h"
#include "document/project_validation.h"
#include "support/error_message.h"
#include "support/json_mutation.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;
using namespace mx::test;

namespace {

// The ProjectError message of fn(), or a null string when nothing is thrown.
template <typename F>
QString projectFileErrorOf(F fn) {
  return mx::test::messageOf<ProjectError>(fn);
}

using mx::test::mutated;

// A JSON array of n valid modes, as the text of a mutation.
QString manyModes(int n) {
  QStringList modes;
  for (int i = 0; i < n; ++i)
    modes << QString("{\"freq_Hz\": %1, \"damping_pct\": 3, \"stiffness_N_per_um\": 10}").arg(500 + 10 * i);
  return "[" + modes.join(", ") + "]";
}

void expectContains(const QString& message, const QStringList& fragments) {
  QVERIFY2(!message.isNull(), "no ProjectError thrown");
  for (const QString& f : fragments)
    QVERIFY2(message.contains(f), qPrintable(QString("'%1' not in: %2").arg(f, message)));
}

}  // namespace

class TestProjectFile : public QObject {
  Q_OBJECT

 private slots:
  void loadsRubioProject() {
    const Project p = loadProject(projectsPath("rubio2006-tool-selection.mxproj"));
    QCOMPARE(p.name, QString("Rubio, De la Sen & Ibeas (2006): tool selection R1 / R2"));
    QVERIFY(p.machine);
    QCOMPARE(p.machine->spindle_power_W, 745.3);
    QCOMPARE(p.machine->max_spindle_rpm.value(), 12000.0);
    QVERIFY(!p.machine->max_feed_mm_s);
    QCOMPARE(p.material->name, QString("Aluminium"));
    QCOMPARE(p.material->Kt_N_mm2, 600.0);
    QCOMPARE(p.material->Kr, 0.3);
    QVERIFY(p.operation->milling == MillingDirection::Up);
    QCOMPARE(p.operation->radial_immersion.value(), 1.0);
    QVERIFY(!p.operation->radial_depth_mm);
    QCOMPARE(p.operation->max_feed_per_tooth_mm, 0.55);
    QCOMPARE(p.tools.size(), std::size_t(2));
    const ToolSpec& r2 = p.tools[1];
    QCOMPARE(r2.id, QString("R2"));
    QCOMPARE(r2.teeth, 2);
    QCOMPARE(r2.diameter_mm, 12.7);
    QCOMPARE(r2.Kr.value(), 0.07);
    QVERIFY(!r2.Kt_N_mm2);
    QCOMPARE(r2.modes_x.size(), std::size_t(1));
    QCOMPARE(r2.modes_x[0].freq_Hz, 900.03);
    QCOMPARE(r2.modes_y[0].damping_pct, 1.38);
    QCOMPARE(r2.modes_y[0].stiffness_N_per_um, 0.971);
    QCOMPARE(p.expert->delta_per_s, 0.05);
    QCOMPARE(p.expert->alpha, 0.95);
    QCOMPARE(p.expert->c, (std::vector<double>{0.2, 0.725, 0.075}));
    QCOMPARE(p.expert->cr, (std::vector<double>{0.8, 0.1, 0.1}));
    QCOMPARE(p.expert->grid->speed_to_rpm, 6000.0);
    QCOMPARE(p.expert->grid->depth_divisions, 10);
    QCOMPARE(p.expert->grid->feed_step_mm, 0.01);
    QVERIFY(p.findTool("R1") == &p.tools[0]);
    QVERIFY(p.findTool("R3") == nullptr);
  }

  void setupForConvertsToSi() {
    const Project p = loadProject(projectsPath("rubio2006-tool-selection.mxproj"));
    const MillingSetup r1 = p.setupFor("R1");
    QCOMPARE(r1.tool_id, std::string("R1"));
    QCOMPARE(r1.teeth, 3);
    QCOMPARE(r1.diameter_m, 0.03);
    QCOMPARE(r1.helix_rad, 0.0);
    QCOMPARE(r1.tangential_coefficient_pa, 6e8);
    QCOMPARE(r1.radial_ratio, 0.3);
    QCOMPARE(r1.modes_x.size(), std::size_t(1));
    QCOMPARE(r1.modes_x[0].natural_frequency_hz, 603.0);
    QCOMPARE(r1.modes_x[0].damping_ratio, 0.039);
    QCOMPARE(r1.modes_x[0].stiffness_n_per_m, 5.59e6);
    QCOMPARE(r1.modes_y[0].natural_frequency_hz, 666.0);
    QCOMPARE(r1.modes_y[0].damping_ratio, 0.035);
    QCOMPARE(r1.modes_y[0].stiffness_n_per_m, 5.715e6);
    QVERIFY(r1.direction == MillingDirection::Up);
    QCOMPARE(r1.radial_depth_m, 0.03);
    QCOMPARE(r1.immersion.entry_rad, 0.0);
    QCOMPARE(r1.immersion.exit_rad, std::numbers::pi);

    const MillingSetup r2 = p.setupFor("R2");
    QCOMPARE(r2.diameter_m, 0.0127);
    QCOMPARE(r2.radial_ratio, 0.07);  // tool override of material.Kr
    QCOMPARE(r2.tangential_coefficient_pa, 6e8);
    QCOMPARE(r2.modes_x[0].stiffness_n_per_m, 0.879e6);
  }

  void setupForInspergerRadialDepth() {
    const Project p = loadProject(projectsPath("benchmark-insperger-1dof.mxproj"));
    QCOMPARE(p.tools.size(), std::size_t(2));
    QCOMPARE(p.material->Kr, 0.3333333333333333);
    QCOMPARE(p.expert->grid->speed_from_rpm, 5000.0);
    QCOMPARE(p.expert->c, ExpertSpec{}.c);  // absent: the default

    const MillingSetup full = p.setupFor("FULL");
    QVERIFY(full.direction == MillingDirection::Down);
    QCOMPARE(full.radial_depth_m, 0.02);
    QCOMPARE(full.immersion.entry_rad, 0.0);
    QCOMPARE(full.immersion.exit_rad, std::numbers::pi);
    QVERIFY(full.modes_y.empty());  // rigid axis

    const MillingSetup low = p.setupFor("LOW");
    QCOMPARE(low.teeth, 2);
    QCOMPARE(low.diameter_m, 0.02);
    QCOMPARE(low.radial_depth_m, 0.001);
    QCOMPARE(low.immersion.entry_rad, std::acos(2.0 * 0.05 - 1.0));
    QCOMPARE(low.immersion.exit_rad, std::numbers::pi);
    QCOMPARE(low.modes_x[0].damping_ratio, 0.011);
    QCOMPARE(low.modes_x[0].stiffness_n_per_m, 1.3400496480507487e6);
    QCOMPARE(low.tangential_coefficient_pa, 6e8);
  }

  void setupForOverridesAndHelix() {
    const Project p = loadProject(fixturePath("valid-full.mxproj"));
    const MillingSetup t1 = p.setupFor("T1");
    QCOMPARE(t1.helix_rad, std::numbers::pi / 6.0);
    QCOMPARE(t1.radial_depth_m, 0.008);  // a/D = 0.5 of D = 16 mm
    QCOMPARE(t1.immersion.entry_rad, std::numbers::pi / 2.0);
    QCOMPARE(t1.tangential_coefficient_pa, 2e9);
    QCOMPARE(t1.radial_ratio, 0.35);
    QCOMPARE(t1.modes_x.size(), std::size_t(2));
    QCOMPARE(t1.modes_x[1].damping_ratio, 0.04);
    QCOMPARE(t1.modes_x[1].stiffness_n_per_m, 2e7);
    const MillingSetup t2 = p.setupFor("T2");
    QCOMPARE(t2.tangential_coefficient_pa, 8e8);
    QCOMPARE(t2.radial_ratio, 0.2);
    QCOMPARE(t2.radial_depth_m, 0.0025);  // the tool's own radial depth
    QCOMPARE(t2.immersion.entry_rad, std::acos(2.0 * 0.25 - 1.0));
    QVERIFY(t2.modes_y.empty());

    Project byDepth = p;
    byDepth.operation->radial_immersion.reset();
    byDepth.operation->radial_depth_mm = 4.0;
    validateProject(byDepth);
    QCOMPARE(byDepth.setupFor("T1").radial_depth_m, 0.004);
    QCOMPARE(byDepth.setupFor("T2").radial_depth_m, 0.0025);
  }

  // The edge and axial coefficients and the process damping: the tool's value, else the material's, else 0,
  // in SI (N/mm -> N/m, N/mm^2 -> N/m^2); they round-trip in the documented key order.
  void edgeForcesAndProcessDamping() {
    const QJsonObject root = mutated(readJson(fixturePath("valid-full.mxproj")),
                                     {"material/Kte_N_mm=27.7", "material/Kre_N_mm=26.6", "material/Ka_N_mm2=222",
                                      "material/Kae_N_mm=0.7", "material/process_damping_N_per_m=2.5e5",
                                      "material/library=\"Al7075-T6\"", "tools/1/Kte_N_mm=40", "tools/1/Ka_N_mm2=0"});
    const Project p = projectFromJson(root);
    validateProject(p);
    const MillingSetup t1 = p.setupFor("T1"), t2 = p.setupFor("T2");
    QCOMPARE(t1.tangential_edge_n_per_m, 27.7e3);
    QCOMPARE(t1.radial_edge_n_per_m, 26.6e3);
    QCOMPARE(t1.axial_coefficient_pa, 222e6);
    QCOMPARE(t1.axial_edge_n_per_m, 0.7e3);
    QCOMPARE(t1.process_damping_n_per_m, 2.5e5);
    QCOMPARE(t2.tangential_edge_n_per_m, 40e3);  // the tool's overrides
    QCOMPARE(t2.axial_coefficient_pa, 0.0);
    QCOMPARE(t2.radial_edge_n_per_m, 26.6e3);
    QCOMPARE(*p.material->library, QString("Al7075-T6"));
    QTemporaryDir dir;
    const QString out = dir.filePath("edges.mxproj");
    saveProject(p, out);
    QCOMPARE(readJson(out), root);
    QVERIFY(*loadProject(out).material == *p.material);
    QCOMPARE(loadProject(out).tools, p.tools);
    const Project plain = loadProject(fixturePath("valid-full.mxproj"));  // K_t and K_r alone: no edge force
    const MillingSetup before = plain.setupFor("T1");
    QCOMPARE(before.tangential_edge_n_per_m + before.radial_edge_n_per_m + before.axial_coefficient_pa +
                 before.axial_edge_n_per_m + before.process_damping_n_per_m,
             0.0);
  }

  void setupForErrors() {
    const Project p = loadProject(fixturePath("valid-full.mxproj"));
    QCOMPARE(projectFileErrorOf([&] { p.setupFor("X9"); }), QString("tool 'X9' not found; available: T1, T2"));

    Project noMaterial = p;
    noMaterial.material.reset();
    QCOMPARE(noMaterial.setupFor("T2").tangential_coefficient_pa, 8e8);  // T2 overrides Kt and Kr
    expectContains(projectFileErrorOf([&] { noMaterial.setupFor("T1"); }),
                   {"section 'material' is missing (needed by tool 'T1'", "Kt_N_mm2 and Kr"});
    noMaterial.tools[1].Kr.reset();
    expectContains(projectFileErrorOf([&] { noMaterial.setupFor("T2"); }), {"section 'material' is missing", "for Kr"});

    Project noOperation = p;
    noOperation.operation.reset();
    expectContains(projectFileErrorOf([&] { noOperation.setupFor("T2"); }),
                   {"section 'operation' is missing (needed by tool 'T2'"});

    Project bare = p;
    bare.machine.reset();
    bare.expert.reset();
    QCOMPARE(p.requireMachine().spindle_power_W, 5000.0);
    QCOMPARE(p.requireExpert().alpha, 0.9);
    expectContains(projectFileErrorOf([&] { bare.requireMachine(); }), {"section 'machine' is missing (needed"});
    expectContains(projectFileErrorOf([&] { bare.requireExpert(); }), {"section 'expert' is missing (needed"});
  }

  void optionalSectionsMayBeAbsent() {
    const QJsonObject root{{"format", "millexpert-project"}, {"version", 1}, {"name", "bare"}};
    const Project p = projectFromJson(root);
    QVERIFY(!p.machine && !p.material && !p.operation && !p.expert);
    QVERIFY(p.tools.empty());
    QCOMPARE(projectFileErrorOf([&] { p.setupFor("A"); }), QString("tool 'A' not found; available: (none)"));
    QCOMPARE(projectToJson(p), root);  // no sections appear on save
  }

  void validationRules_data() {
    QTest::addColumn<QStringList>("mutations");
    QTest::addColumn<QStringList>("expected");
    auto row = [](const char* name, const QStringList& mutations, const QStringList& expected) {
      QTest::newRow(name) << mutations << expected;
    };
    // header
    row("format wrong", {"format=\"other-app\""}, {"format = \"other-app\": must be \"millexpert-project\""});
    row("format missing", {"-format"}, {"format: missing (required string \"millexpert-project\")"});
    row("version newer", {"version=2"}, {"version = 2: ", "newer MillExpert", "version 1"});
    row("version zero", {"version=0"}, {"version = 0: must be 1"});
    row("version string", {"version=\"1\""}, {"version: expected a number, got string"});
    row("name missing", {"-name"}, {"name: missing (required string)"});
    row("name number", {"name=3"}, {"name: expected a string, got number"});
    // section and element types
    row("machine array", {"machine=[]"}, {"machine: expected an object, got array"});
    row("material string", {"material=\"steel\""}, {"material: expected an object, got string"});
    row("tools object", {"tools={}"}, {"tools: expected an array, got object"});
    row("tool number", {"tools/1=5"}, {"tools[1]: expected an object, got number"});
    // machine
    row("power missing", {"-machine/spindle_power_W"}, {"machine.spindle_power_W: missing (required number > 0)"});
    row("power zero", {"machine/spindle_power_W=0"}, {"machine.spindle_power_W = 0: must be in (0, 1e+06]"});
    row("power negative", {"machine/spindle_power_W=-745.3"},
        {"machine.spindle_power_W = -745.3: must be in (0, 1e+06]"});
    row("power string", {"machine/spindle_power_W=\"5kW\""},
        {"machine.spindle_power_W: expected a number, got string"});
    row("power infinite", {"machine/spindle_power_W=inf"},
        {"machine.spindle_power_W = inf: must be a finite number in (0, 1e+06]"});
    row("max rpm zero", {"machine/max_spindle_rpm=0"}, {"machine.max_spindle_rpm = 0: must be in (0, 1e+05]"});
    row("max rpm string", {"machine/max_spindle_rpm=\"fast\""},
        {"machine.max_spindle_rpm: expected a number, got string"});
    row("max feed negative", {"machine/max_feed_mm_s=-1"}, {"machine.max_feed_mm_s = -1: must be in (0, 1e+05]"});
    row("torque zero", {"machine/max_torque_Nm=0"}, {"machine.max_torque_Nm = 0: must be in (0, 1e+05]"});
    row("torque negative", {"machine/max_torque_Nm=-9"}, {"machine.max_torque_Nm = -9: must be in (0, 1e+05]"});
    row("torque too large", {"machine/max_torque_Nm=2e5"}, {"machine.max_torque_Nm = 2e+05: must be in (0, 1e+05]"});
    row("torque infinite", {"machine/max_torque_Nm=inf"},
        {"machine.max_torque_Nm = inf: must be a finite number in (0, 1e+05]"});
    row("torque string", {"machine/max_torque_Nm=\"9 Nm\""}, {"machine.max_torque_Nm: expected a number, got string"});
    const QString curve =
        "machine/spindle_curve=[{\"speed_rpm\": 1000, \"power_W\": 2000}, "
        "{\"speed_rpm\": 3000, \"power_W\": 4000}, {\"speed_rpm\": 6000, \"power_W\": 3000}]";
    row("curve object", {"machine/spindle_curve={}"}, {"machine.spindle_curve: expected an array, got object"});
    row("curve one row", {curve, "-machine/spindle_curve/2", "-machine/spindle_curve/1"},
        {"machine.spindle_curve has 1 row(s): must have at least 2 rows of speed_rpm and power_W"});
    row("curve empty", {"machine/spindle_curve=[]"}, {"machine.spindle_curve has 0 row(s): must have at least 2"});
    row("curve row number", {curve, "machine/spindle_curve/1=5"},
        {"machine.spindle_curve[1]: expected an object, got number"});
    row("curve speed missing", {curve, "-machine/spindle_curve/0/speed_rpm"},
        {"machine.spindle_curve[0].speed_rpm: missing (required number >= 0)"});
    row("curve power string", {curve, "machine/spindle_curve/1/power_W=\"4 kW\""},
        {"machine.spindle_curve[1].power_W: expected a number, got string"});
    row("curve speed negative", {curve, "machine/spindle_curve/0/speed_rpm=-100"},
        {"machine.spindle_curve[0].speed_rpm = -100: must be in [0, 1e+05]"});
    row("curve speeds not increasing", {curve, "machine/spindle_curve/2/speed_rpm=3000"},
        {"machine.spindle_curve[2].speed_rpm = 3000: must be > 3000 (machine.spindle_curve[1].speed_rpm: speeds "
         "strictly increasing)"});
    row("curve speeds decreasing", {curve, "machine/spindle_curve/2/speed_rpm=2500"},
        {"machine.spindle_curve[2].speed_rpm = 2500: must be > 3000"});
    row("curve power negative", {curve, "machine/spindle_curve/1/power_W=-1"},
        {"machine.spindle_curve[1].power_W = -1: must be in [0, 1e+06]"});
    row("curve power infinite", {curve, "machine/spindle_curve/2/power_W=inf"},
        {"machine.spindle_curve[2].power_W = inf: must be a finite number in [0, 1e+06]"});
    // material
    row("Kt missing", {"-material/Kt_N_mm2"}, {"material.Kt_N_mm2: missing (required number > 0)"});
    row("Kt zero", {"material/Kt_N_mm2=0"}, {"material.Kt_N_mm2 = 0: must be in (0, 1e+05]"});
    row("Kt nan", {"material/Kt_N_mm2=nan"}, {"material.Kt_N_mm2 = nan: must be a finite number in (0, 1e+05]"});
    row("Kr negative", {"material/Kr=-0.1"}, {"material.Kr = -0.1: must be in [0, 10]"});
    row("Kr missing", {"-material/Kr"}, {"material.Kr: missing (required number >= 0)"});
    row("material name missing", {"-material/name"}, {"material.name: missing (required string)"});
    row("Kte negative", {"material/Kte_N_mm=-1"}, {"material.Kte_N_mm = -1: must be in [0, 10000]"});
    row("Kre too large", {"material/Kre_N_mm=20000"}, {"material.Kre_N_mm = 20000: must be in [0, 10000]"});
    row("Ka string", {"material/Ka_N_mm2=\"200\""}, {"material.Ka_N_mm2: expected a number, got string"});
    row("Kae nan", {"material/Kae_N_mm=nan"}, {"material.Kae_N_mm = nan: must be a finite number in [0, 10000]"});
    row("process damping too large", {"material/process_damping_N_per_m=2e9"},
        {"material.process_damping_N_per_m = 2e+09: must be in [0, 1e+09]"});
    row("library number", {"material/library=7"}, {"material.library: expected a string, got number"});
    row("tool Kte negative", {"tools/0/Kte_N_mm=-5"}, {"tools[0].Kte_N_mm = -5: must be in [0, 10000]"});
    row("tool Ka too large", {"tools/0/Ka_N_mm2=1e6"}, {"tools[0].Ka_N_mm2 = 1e+06: must be in [0, 1e+05]"});
    // operation
    row("milling invalid", {"operation/milling=\"sideways\""},
        {"operation.milling = \"sideways\": must be \"up\" or \"down\""});
    row("milling missing", {"-operation/milling"}, {"operation.milling: missing (required string)"});
    row("milling boolean", {"operation/milling=true"}, {"operation.milling: expected a string, got boolean"});
    row("immersion zero", {"operation/radial_immersion=0"}, {"operation.radial_immersion = 0: must be in (0, 1]"});
    row("immersion above one", {"operation/radial_immersion=1.5"},
        {"operation.radial_immersion = 1.5: must be in (0, 1]"});
    row("immersion and depth", {"operation/radial_depth_mm=4"},
        {"operation: radial_immersion = 0.5 and radial_depth_mm = 4", "exactly one"});
    row("no radial engagement", {"-operation/radial_immersion"},
        {"operation.radial_immersion: missing (required number in (0, 1], or operation.radial_depth_mm"});
    row("operation depth above D", {"-operation/radial_immersion", "operation/radial_depth_mm=20"},
        {"operation.radial_depth_mm = 20: must be in (0, 16]", "tools[0].diameter_mm = 16", "'T1'"});
    row("operation depth zero", {"-operation/radial_immersion", "operation/radial_depth_mm=0"},
        {"operation.radial_depth_mm = 0: must be > 0"});
    row("max feed per tooth zero", {"operation/max_feed_per_tooth_mm=0"},
        {"operation.max_feed_per_tooth_mm = 0: must be in (0, 10]"});
    row("max feed per tooth missing", {"-operation/max_feed_per_tooth_mm"},
        {"operation.max_feed_per_tooth_mm: missing (required number > 0)"});
    // tools
    row("id missing", {"-tools/0/id"}, {"tools[0].id: missing (required string)"});
    row("id number", {"tools/0/id=7"}, {"tools[0].id: expected a string, got number"});
    row("id empty", {"tools/0/id=\"\""}, {"tools[0].id = \"\": must be a non-empty string"});
    row("duplicate ids", {"tools/1/id=\"T1\""}, {"tools[1].id = \"T1\": duplicate of tools[0].id"});
    row("teeth zero", {"tools/0/teeth=0"}, {"tools[0].teeth = 0: must be an integer in [1, 100]"});
    row("teeth negative", {"tools/1/teeth=-2"}, {"tools[1].teeth = -2: must be an integer in [1, 100]"});
    row("teeth fractional", {"tools/0/teeth=2.5"}, {"tools[0].teeth = 2.5: must be an integer in [1, 100]"});
    row("teeth 101", {"tools/0/teeth=101"}, {"tools[0].teeth = 101: must be an integer in [1, 100]"});
    row("teeth a million", {"tools/1/teeth=1000000"}, {"tools[1].teeth = 1e+06: must be an integer in [1, 100]"});
    row("teeth missing", {"-tools/0/teeth"}, {"tools[0].teeth: missing (required integer in [1, 100])"});
    row("teeth string", {"tools/0/teeth=\"4\""}, {"tools[0].teeth: expected a number, got string"});
    row("diameter zero", {"tools/0/diameter_mm=0"}, {"tools[0].diameter_mm = 0: must be in (0, 1000]"});
    row("diameter negative", {"tools/1/diameter_mm=-10"}, {"tools[1].diameter_mm = -10: must be in (0, 1000]"});
    row("diameter string", {"tools/0/diameter_mm=\"16\""}, {"tools[0].diameter_mm: expected a number, got string"});
    row("diameter infinite", {"tools/0/diameter_mm=inf"},
        {"tools[0].diameter_mm = inf: must be a finite number in (0, 1000]"});
    row("diameter missing", {"-tools/1/diameter_mm"}, {"tools[1].diameter_mm: missing (required number > 0)"});
    row("helix missing", {"-tools/0/helix_deg"}, {"tools[0].helix_deg: missing (required number in (-90, 90))"});
    row("helix 90", {"tools/0/helix_deg=90"}, {"tools[0].helix_deg = 90: must be in (-90, 90)"});
    // cutter geometry: T1 has 4 teeth and D = 16 mm (runout below 4000 um), T2 has 2 teeth and D = 10 mm
    row("pitch object", {"tools/0/pitch_deg={}"}, {"tools[0].pitch_deg: expected an array, got object"});
    row("pitch string", {"tools/1/pitch_deg=[\"180\", 180]"}, {"tools[1].pitch_deg[0]: expected a number, got string"});
    row("pitch too short", {"tools/0/pitch_deg=[90, 90, 180]"},
        {"tools[0].pitch_deg = [90, 90, 180]: must have one value per tooth (teeth = 4), got 3"});
    row("pitch too long", {"tools/1/pitch_deg=[120, 120, 120]"},
        {"tools[1].pitch_deg = [120, 120, 120]: must have one value per tooth (teeth = 2), got 3"});
    row("pitch empty", {"tools/1/pitch_deg=[]"},
        {"tools[1].pitch_deg = []: must have one value per tooth (teeth = 2)"});
    row("teeth without their pitch", {"tools/0/pitch_deg=[70, 110, 70, 110]", "tools/0/teeth=3"},
        {"tools[0].pitch_deg = [70, 110, 70, 110]: must have one value per tooth (teeth = 3), got 4"});
    row("pitch zero", {"tools/0/pitch_deg=[0, 180, 90, 90]"}, {"tools[0].pitch_deg[0] = 0: must be in (0, 360)"});
    row("pitch negative", {"tools/0/pitch_deg=[90, -10, 190, 90]"},
        {"tools[0].pitch_deg[1] = -10: must be in (0, 360)"});
    row("pitch 360", {"tools/1/pitch_deg=[0.5, 360]"}, {"tools[1].pitch_deg[1] = 360: must be in (0, 360)"});
    row("pitch nan", {"tools/1/pitch_deg=[180, 180]", "tools/1/pitch_deg/1=nan"},
        {"tools[1].pitch_deg[1] = nan: must be a finite number in (0, 360)"});
    row("pitch sum 1e-5 high", {"tools/0/pitch_deg=[70, 110, 70, 110.00001]"},
        {"tools[0].pitch_deg = [70, 110, 70, 110.00001]: must sum to 360 within 1e-06, sums to 360.00001"});
    row("pitch sum 1e-5 low", {"tools/1/pitch_deg=[180, 179.99999]"},
        {"tools[1].pitch_deg = [180, 179.99999]: must sum to 360 within 1e-06, sums to 359.99999"});
    row("runout string", {"tools/1/runout_um=[0, \"8\"]"}, {"tools[1].runout_um[1]: expected a number, got string"});
    row("runout too short", {"tools/0/runout_um=[0, 8]"},
        {"tools[0].runout_um = [0, 8]: must have one value per tooth (teeth = 4), got 2"});
    row("runout D/4", {"tools/0/runout_um=[0, 4000, 0, 0]"},
        {"tools[0].runout_um[1] = 4000: must be in (-4000, 4000) (|runout| < D/4 = 250 * diameter_mm, diameter_mm = "
         "16)"});
    row("runout -D/4", {"tools/1/runout_um=[-2500, 0]"}, {"tools[1].runout_um[0] = -2500: must be in (-2500, 2500)"});
    row("runout infinite", {"tools/1/runout_um=[0, 0]", "tools/1/runout_um/1=inf"},
        {"tools[1].runout_um[1] = inf: must be a finite number in (-2500, 2500)"});
    row("tool Kt zero", {"tools/1/Kt_N_mm2=0"}, {"tools[1].Kt_N_mm2 = 0: must be in (0, 1e+05]"});
    row("tool Kr negative", {"tools/1/Kr=-0.2"}, {"tools[1].Kr = -0.2: must be in [0, 10]"});
    row("tool Kr string", {"tools/1/Kr=\"low\""}, {"tools[1].Kr: expected a number, got string"});
    row("tool depth above D", {"tools/1/radial_depth_mm=12"},
        {"tools[1].radial_depth_mm = 12: must be in (0, 10]", "tools[1].diameter_mm = 10"});
    row("tool depth zero", {"tools/1/radial_depth_mm=0"}, {"tools[1].radial_depth_mm = 0: must be in (0, 10]"});
    row("tool depth just above D", {"tools/0/radial_depth_mm=16.5"},
        {"tools[0].radial_depth_mm = 16.5: must be in (0, 16]"});
    row("tool depth with D 0", {"tools/1/diameter_mm=0"}, {"tools[1].diameter_mm = 0: must be in (0, 1000]"});
    row("tool force zero", {"tools/0/max_force_N=0"}, {"tools[0].max_force_N = 0: must be in (0, 1e+07]"});
    row("tool force negative", {"tools/1/max_force_N=-50"}, {"tools[1].max_force_N = -50: must be in (0, 1e+07]"});
    row("tool force too large", {"tools/0/max_force_N=2e7"}, {"tools[0].max_force_N = 2e+07: must be in (0, 1e+07]"});
    row("tool force infinite", {"tools/0/max_force_N=inf"},
        {"tools[0].max_force_N = inf: must be a finite number in (0, 1e+07]"});
    row("tool force string", {"tools/0/max_force_N=\"600 N\""},
        {"tools[0].max_force_N: expected a number, got string"});
    // modes
    row("modes_x missing", {"-tools/0/modes_x"}, {"tools[0].modes_x: missing (required array of modes"});
    row("modes_y object", {"tools/0/modes_y={}"}, {"tools[0].modes_y: expected an array, got object"});
    row("mode number", {"tools/0/modes_x/1=3"}, {"tools[0].modes_x[1]: expected an object, got number"});
    row("damping 150", {"tools/1/modes_x/0/damping_pct=150"},
        {"tools[1].modes_x[0].damping_pct = 150: must be in [0.001, 100)"});
    row("damping zero", {"tools/0/modes_y/0/damping_pct=0"},
        {"tools[0].modes_y[0].damping_pct = 0: must be in [0.001, 100)"});
    row("damping 100", {"tools/0/modes_x/1/damping_pct=100"},
        {"tools[0].modes_x[1].damping_pct = 100: must be in [0.001, 100)"});
    row("damping nan", {"tools/0/modes_x/0/damping_pct=nan"},
        {"tools[0].modes_x[0].damping_pct = nan: must be a finite number in [0.001, 100)"});
    row("damping missing", {"-tools/0/modes_y/0/damping_pct"},
        {"tools[0].modes_y[0].damping_pct: missing (required number in (0, 100))"});
    row("stiffness zero", {"tools/0/modes_x/1/stiffness_N_per_um=0"},
        {"tools[0].modes_x[1].stiffness_N_per_um = 0: must be in [0.001, 1e+06]"});
    row("stiffness negative", {"tools/1/modes_x/0/stiffness_N_per_um=-2"},
        {"tools[1].modes_x[0].stiffness_N_per_um = -2: must be in [0.001, 1e+06]"});
    row("stiffness string", {"tools/1/modes_x/0/stiffness_N_per_um=\"2\""},
        {"tools[1].modes_x[0].stiffness_N_per_um: expected a number, got string"});
    row("frequency zero", {"tools/0/modes_y/0/freq_Hz=0"}, {"tools[0].modes_y[0].freq_Hz = 0: must be in (0, 20000]"});
    row("frequency -inf", {"tools/0/modes_y/0/freq_Hz=-inf"},
        {"tools[0].modes_y[0].freq_Hz = -inf: must be a finite number in (0, 20000]"});
    row("frequency missing", {"-tools/0/modes_x/0/freq_Hz"},
        {"tools[0].modes_x[0].freq_Hz: missing (required number > 0)"});
    // expert
    row("delta negative", {"expert/delta_per_s=-0.05"}, {"expert.delta_per_s = -0.05: must be in [0, 10000]"});
    row("delta missing", {"-expert/delta_per_s"}, {"expert.delta_per_s: missing (required number >= 0)"});
    row("alpha zero", {"expert/alpha=0"}, {"expert.alpha = 0: must be in (0, 1]"});
    row("alpha above one", {"expert/alpha=1.2"}, {"expert.alpha = 1.2: must be in (0, 1]"});
    row("alpha missing", {"-expert/alpha"}, {"expert.alpha: missing (required number in (0, 1])"});
    row("c too short", {"expert/c=[0.5, 0.5]"}, {"expert.c = [0.5, 0.5]: must be an array of 3 numbers >= 0, got 2"});
    row("cr negative", {"expert/cr/1=-0.1"}, {"expert.cr[1] = -0.1: must be >= 0"});
    row("ct string element", {"expert/ct/0=\"a\""}, {"expert.ct[0]: expected a number, got string"});
    row("cf not array", {"expert/cf=0.5"}, {"expert.cf: expected an array, got number"});
    row("cf infinite", {"expert/cf/1=inf"}, {"expert.cf[1] = inf: must be a finite number >= 0"});
    row("grid array", {"expert/grid=[]"}, {"expert.grid: expected an object, got array"});
    row("grid from zero", {"expert/grid/speed_from_rpm=0"}, {"expert.grid.speed_from_rpm = 0: must be in (0, 1e+05]"});
    row("grid from equals to", {"expert/grid/speed_to_rpm=2000"},
        {"expert.grid.speed_to_rpm = 2000: must be > expert.grid.speed_from_rpm = 2000"});
    row("grid step zero", {"expert/grid/speed_step_rpm=0"}, {"expert.grid.speed_step_rpm = 0: must be in (0, 1e+05]"});
    row("grid divisions zero", {"expert/grid/depth_divisions=0"},
        {"expert.grid.depth_divisions = 0: must be an integer >= 1"});
    row("grid divisions fractional", {"expert/grid/depth_divisions=2.5"},
        {"expert.grid.depth_divisions = 2.5: must be an integer >= 1"});
    row("grid feed step negative", {"expert/grid/feed_step_mm=-0.01"},
        {"expert.grid.feed_step_mm = -0.01: must be in [1e-04, 10]"});
    row("grid field missing", {"-expert/grid/feed_step_mm"},
        {"expert.grid.feed_step_mm: missing (required number > 0)"});
    // tap-test FRF references
    row("frf not object", {"tools/0/frf_x=\"taps/x.uff\""}, {"tools[0].frf_x: expected an object, got string"});
    row("frf file missing", {"tools/0/frf_x={\"dataset\":0}"}, {"tools[0].frf_x.file: missing (required string)"});
    row("frf file number", {"tools/0/frf_y={\"file\":3}"}, {"tools[0].frf_y.file: expected a string, got number"});
    row("frf file blank", {"tools/1/frf_x={\"file\":\" \"}"},
        {"tools[1].frf_x.file = \" \": must name a UFF 58/58b or CSV file"});
    row("frf dataset negative", {"tools/0/frf_x={\"file\":\"x.uff\",\"dataset\":-1}"},
        {"tools[0].frf_x.dataset = -1: must be an integer >= 0"});
    row("frf dataset fraction", {"tools/0/frf_x={\"file\":\"x.uff\",\"dataset\":0.5}"},
        {"tools[0].frf_x.dataset = 0.5: must be an integer >= 0"});
    row("frf dataset string", {"tools/0/frf_x={\"file\":\"x.uff\",\"dataset\":\"1\"}"},
        {"tools[0].frf_x.dataset: expected a number, got string"});
    row("frf quantity unknown", {"tools/0/frf_y={\"file\":\"y.csv\",\"quantity\":\"force\"}"},
        {"tools[0].frf_y.quantity = \"force\": must be \"receptance\", \"mobility\" or \"accelerance\""});
    row("modes missing without frf", {"-tools/0/modes_y"}, {"tools[0].modes_y: missing"});
    // the physical ranges that bound every model's work and keep its numbers finite
    row("Kt 1e308", {"material/Kt_N_mm2=1e308"}, {"material.Kt_N_mm2 = 1e+308: must be in (0, 1e+05]"});
    row("Kr 11", {"material/Kr=11"}, {"material.Kr = 11: must be in [0, 10]"});
    row("power 2 MW", {"machine/spindle_power_W=2e6"}, {"machine.spindle_power_W = 2e+06: must be in (0, 1e+06]"});
    row("max rpm 1e6", {"machine/max_spindle_rpm=1e6"}, {"machine.max_spindle_rpm = 1e+06: must be in (0, 1e+05]"});
    row("feed per tooth 11", {"operation/max_feed_per_tooth_mm=11"},
        {"operation.max_feed_per_tooth_mm = 11: must be in (0, 10]"});
    row("diameter 1e308", {"tools/0/diameter_mm=1e308"}, {"tools[0].diameter_mm = 1e+308: must be in (0, 1000]"});
    row("tool Kt 1e308", {"tools/1/Kt_N_mm2=1e308"}, {"tools[1].Kt_N_mm2 = 1e+308: must be in (0, 1e+05]"});
    row("mode frequency 1.797e308", {"tools/0/modes_x/0/freq_Hz=1.797e308"},
        {"tools[0].modes_x[0].freq_Hz = 1.797e+308: must be in (0, 20000]"});
    row("mode frequency 1e5", {"tools/0/modes_y/0/freq_Hz=1e5"},
        {"tools[0].modes_y[0].freq_Hz = 1e+05: must be in (0, 20000]"});
    row("damping 1e-300", {"tools/0/modes_x/1/damping_pct=1e-300"},
        {"tools[0].modes_x[1].damping_pct = 1e-300: must be in [0.001, 100)"});
    row("stiffness 1e9", {"tools/0/modes_x/1/stiffness_N_per_um=1e9"},
        {"tools[0].modes_x[1].stiffness_N_per_um = 1e+09: must be in [0.001, 1e+06]"});
    row("51 modes", {"tools/0/modes_x=" + manyModes(51)}, {"tools[0].modes_x has 51 modes: at most 50 are allowed"});
    row("delta 1e5", {"expert/delta_per_s=1e5"}, {"expert.delta_per_s = 1e+05: must be in [0, 10000]"});
    // T1's first x mode decays at 2.5 % of 2 pi 1200 Hz = 188.5 1/s (its y mode, 172.8 1/s, comes later)
    row("delta at a mode's decay rate", {"expert/delta_per_s=188.5"},
        {"expert.delta_per_s = 188.5: must be in [0, 188.49555921538757) 1/s, below the decay rate zeta omega_n of "
         "tools[0].modes_x[0]"});
    row("grid to 1e308", {"expert/grid/speed_to_rpm=1e308"},
        {"expert.grid.speed_to_rpm = 1e+308: must be in (0, 1e+05]"});
    row("grid divisions 1e6", {"expert/grid/depth_divisions=1e6"},
        {"expert.grid.depth_divisions = 1e+06: must be an integer in [1, 1000]"});
    row("grid feed step 1e-5", {"expert/grid/feed_step_mm=1e-5"},
        {"expert.grid.feed_step_mm = 1e-05: must be in [1e-04, 10]"});
    row("grid cells", {"expert/grid/speed_step_rpm=0.06"},
        {"expert.grid: 300001 speeds (speed_from_rpm = 2000 to speed_to_rpm = 20000 by speed_step_rpm = 0.06) x "
         "depth_divisions = 8 = 2400008 cells: at most 1e+06; raise expert.grid.speed_step_rpm or lower "
         "expert.grid.depth_divisions"});
    row("grid points", {"expert/grid/depth_divisions=100", "expert/grid/feed_step_mm=0.0001"},
        {"expert.grid: 91 speeds",
         "x depth_divisions = 100 x 2000 feeds (operation.max_feed_per_tooth_mm = 0.2 by "
         "feed_step_mm = 1e-04) = 18200000 points: at most 5e+06"});
    // operating_point: a tool of the project, and the ranges of the spindle, the presets' depths and the feed
    row("point not an object", {"operating_point=[]"}, {"operating_point: expected an object, got array"});
    row("point tool unknown", {"operating_point/tool=\"T9\""},
        {"operating_point.tool = \"T9\": must be the id of a tool of the project"});
    row("point tool removed", {"-tools/0"}, {"operating_point.tool = \"T1\": must be the id of a tool of the project"});
    row("point tool missing", {"-operating_point/tool"}, {"operating_point.tool: missing (required string)"});
    row("point tool number", {"operating_point/tool=1"}, {"operating_point.tool: expected a string, got number"});
    row("point speed missing", {"-operating_point/speed_rpm"},
        {"operating_point.speed_rpm: missing (required number in (0, 1e+05])"});
    row("point speed string", {"operating_point/speed_rpm=\"8000\""},
        {"operating_point.speed_rpm: expected a number, got string"});
    row("point speed null", {"operating_point/speed_rpm=null"}, {"operating_point.speed_rpm: expected a number"});
    row("point speed 0", {"operating_point/speed_rpm=0"}, {"operating_point.speed_rpm = 0: must be in (0, 1e+05]"});
    row("point speed above 1e5", {"operating_point/speed_rpm=100000.5"},
        {"operating_point.speed_rpm = 100000.5: must be in (0, 1e+05]"});
    row("point speed nan", {"operating_point/speed_rpm=nan"},
        {"operating_point.speed_rpm = nan: must be a finite number in (0, 1e+05]"});
    row("point depth missing", {"-operating_point/depth_mm"},
        {"operating_point.depth_mm: missing (required number in (0, 1000])"});
    row("point depth 0", {"operating_point/depth_mm=0"}, {"operating_point.depth_mm = 0: must be in (0, 1000]"});
    row("point depth negative", {"operating_point/depth_mm=-1"},
        {"operating_point.depth_mm = -1: must be in (0, 1000]"});
    row("point depth above 1000", {"operating_point/depth_mm=1000.001"},
        {"operating_point.depth_mm = 1000.001: must be in (0, 1000]"});
    row("point depth inf", {"operating_point/depth_mm=inf"},
        {"operating_point.depth_mm = inf: must be a finite number in (0, 1000]"});
    row("point feed missing", {"-operating_point/feed_mm_per_tooth"},
        {"operating_point.feed_mm_per_tooth: missing (required number in (0, 10])"});
    row("point feed 0", {"operating_point/feed_mm_per_tooth=0"},
        {"operating_point.feed_mm_per_tooth = 0: must be in (0, 10]"});
    row("point feed above 10", {"operating_point/feed_mm_per_tooth=10.5"},
        {"operating_point.feed_mm_per_tooth = 10.5: must be in (0, 10]"});
    row("point feed bool", {"operating_point/feed_mm_per_tooth=true"},
        {"operating_point.feed_mm_per_tooth: expected a number, got boolean"});
  }

  // The count of tools is bounded: 100 pass, 101 are refused before any tool is looked at.
  void toolCountLimit() {
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    QJsonArray tools;
    for (int i = 0; i < 100; ++i) {
      QJsonObject tool = base["tools"].toArray().at(0).toObject();
      tool["id"] = QString("T%1").arg(i);
      tools.append(tool);
    }
    QJsonObject project = base;
    project["tools"] = tools;
    QCOMPARE(projectFromJson(project).tools.size(), std::size_t(100));
    tools.append(tools.at(0));
    project["tools"] = tools;
    QCOMPARE(projectFileErrorOf([&] { projectFromJson(project); }),
             QString("tools has 101 tools: at most 100 are allowed"));
  }

  void validationRules() {
    QFETCH(QStringList, mutations);
    QFETCH(QStringList, expected);
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    projectFromJson(base);  // the base itself is valid
    expectContains(projectFileErrorOf([&] { projectFromJson(mutated(base, mutations)); }), expected);
  }

  void validRelaxations() {
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    // optional fields and sections may be absent; rigid axes and many modes are fine
    const Project p = projectFromJson(
        mutated(base, {"-machine/max_spindle_rpm", "-machine/max_feed_mm_s", "-expert/c", "-expert/grid",
                       "-tools/0/modes_x", "tools/0/modes_x=[]", "-material", "operation/radial_immersion=1"}));
    QVERIFY(!p.machine->max_spindle_rpm && !p.machine->max_feed_mm_s && !p.expert->grid);
    QCOMPARE(p.expert->c, ExpertSpec{}.c);
    QVERIFY(p.tools[0].modes_x.empty());
    const Project depth = projectFromJson(
        mutated(base, {"-operation/radial_immersion", "operation/radial_depth_mm=16", "tools/1/radial_depth_mm=10"}));
    QCOMPARE(depth.setupFor("T1").immersion.exit_rad, std::numbers::pi);  // a = D: full immersion
  }

  // The edges of the cutter-geometry rules that pass, and the SI conversion of setupFor.
  void cutterGeometryToSi() {
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    const Project p = projectFromJson(
        mutated(base, {"tools/0/pitch_deg=[70, 110, 70, 110.0000009]", "tools/0/runout_um=[0, 3999.9, 0, -5]",
                       "tools/1/pitch_deg=[1e-9, 359.999999999]", "tools/1/runout_um=[-2499.99, 0]"}));
    const MillingSetup t1 = p.setupFor("T1");
    QCOMPARE(t1.pitch_rad.size(), std::size_t(4));
    QCOMPARE(t1.pitch_rad[1], 110.0 * std::numbers::pi / 180.0);
    QCOMPARE(t1.runout_m[1], 3999.9e-6);
    QCOMPARE(t1.runout_m[3], -5e-6);
    QCOMPARE(t1.helix_rad, std::numbers::pi / 6.0);
    QVERIFY(!t1.uniformPitch());
    t1.validateGeometry();  // the engine agrees with the document's rules
    QCOMPARE(t1.toothAngleRad(2), std::numbers::pi);
    p.setupFor("T2").validateGeometry();
    const MillingSetup uniform = loadProject(fixturePath("valid-full.mxproj")).setupFor("T1");
    QVERIFY(uniform.pitch_rad.empty() && uniform.runout_m.empty());
  }

  void cutterGeometryRoundTrip_data() {
    QTest::addColumn<QStringList>("mutations");
    QTest::newRow("variable pitch") << QStringList{"tools/0/pitch_deg=[70, 110, 70, 110]"};
    QTest::newRow("runout only") << QStringList{"tools/1/runout_um=[0, -12.5]"};
    QTest::newRow("both") << QStringList{"tools/0/pitch_deg=[85, 95, 85, 95]", "tools/0/runout_um=[0, 8, 0, -5]"};
    QTest::newRow("sum within 1e-6") << QStringList{"tools/1/pitch_deg=[179.9999995, 180]"};
    QTest::newRow("shortest text") << QStringList{"tools/1/pitch_deg=[0.1, 359.9]", "tools/1/runout_um=[0.3, 1e-3]"};
  }

  void cutterGeometryRoundTrip() {
    QFETCH(QStringList, mutations);
    const QJsonObject root = mutated(readJson(fixturePath("valid-full.mxproj")), mutations);
    const Project p = projectFromJson(root);
    QTemporaryDir dir;
    const QString out = dir.filePath("geometry.mxproj");
    saveProject(p, out);
    QCOMPARE(readJson(out), root);
    QCOMPARE(loadProject(out).tools, p.tools);
    QFile text(out);
    QVERIFY(text.open(QIODevice::ReadOnly));
    const QByteArray saved = text.readAll();
    const qsizetype helix = saved.indexOf("\"helix_deg\"");
    for (const char* key : {"\"pitch_deg\"", "\"runout_um\""}) {
      const qsizetype at = saved.indexOf(key);
      if (at >= 0) QVERIFY2(at > helix && at < saved.indexOf("\"Kt_N_mm2\"", helix), key);  // documented order
    }
    Project cleared = p;
    for (ToolSpec& t : cleared.tools) t.pitch_deg.reset(), t.runout_um.reset();
    for (const auto& t : projectToJson(cleared)["tools"].toArray())
      QVERIFY(!t.toObject().contains("pitch_deg") && !t.toObject().contains("runout_um"));
  }

  void frfReferencesReplaceModes() {
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    // an axis with an FRF needs no modes; dataset and quantity are optional
    const Project p = projectFromJson(mutated(
        base, {"-tools/0/modes_x", "tools/0/frf_x={\"file\":\"taps/T9-x.uff\"}",
               "tools/0/frf_y={\"file\":\"taps/T9-y.csv\",\"dataset\":1,\"quantity\":\"accelerance\",\"note\":7}"}));
    const ToolSpec& t = p.tools[0];
    QVERIFY(t.modes_x.empty() && !t.modes_y.empty() && t.hasFrf());
    QCOMPARE(t.frf_x->file, QString("taps/T9-x.uff"));
    QCOMPARE(t.frf_x->datasetIndex(), 0);
    QVERIFY(!t.frf_x->dataset && !t.frf_x->quantity);
    QCOMPARE(t.frf_y->datasetIndex(), 1);
    QCOMPARE(*t.frf_y->quantity, QString("accelerance"));
    // written back as read: no modes_x key, the unknown key kept, absent dataset stays absent
    const QJsonObject tool = projectToJson(p).value("tools").toArray().at(0).toObject();
    QVERIFY(!tool.contains("modes_x"));
    QCOMPARE(tool.value("frf_x").toObject(), (QJsonObject{{"file", "taps/T9-x.uff"}}));
    QCOMPARE(tool.value("frf_y").toObject().value("note").toInt(), 7);
    QCOMPARE(projectFromJson(projectToJson(p)).tools[0], t);
  }

  void loadErrorsNameTheFile() {
    const QString missing = fixturePath("does-not-exist.mxproj");
    expectContains(projectFileErrorOf([&] { loadProject(missing); }), {missing, "not found"});
    expectContains(projectFileErrorOf([&] { loadProject(fixturePath("invalid-nan.mxproj")); }),
                   {"invalid-nan.mxproj: invalid JSON at line 5, column 50", "illegal number"});
    expectContains(projectFileErrorOf([&] { loadProject(fixturePath("invalid-overflow.mxproj")); }),
                   {"invalid-overflow.mxproj: invalid JSON at line 5", "illegal number"});
    expectContains(projectFileErrorOf([&] { loadProject(fixturePath("invalid-syntax.mxproj")); }),
                   {"invalid-syntax.mxproj: invalid JSON at line 5, column 2"});

    QTemporaryDir dir;
    const QString bad = dir.filePath("bad.mxproj");
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QJsonDocument(mutated(readJson(fixturePath("valid-full.mxproj")), {"tools/0/teeth=0"})).toJson());
    f.close();
    QCOMPARE(projectFileErrorOf([&] { loadProject(bad); }),
             bad + ": tools[0].teeth = 0: must be an integer in [1, 100]");
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write("[1, 2]");
    f.close();
    expectContains(projectFileErrorOf([&] { loadProject(bad); }), {bad, "top level must be a JSON object"});
  }

  // A tool library: a bare array or an object with "tools"; errors as for a project.
  void toolsFromJsonReadsALibrary_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("error");
    const QByteArray tool = R"({"id": "E", "teeth": 2, "diameter_mm": 16, "helix_deg": 30, "x_shop": 7,
        "modes_x": [{"freq_Hz": 900, "damping_pct": 3, "stiffness_N_per_um": 8}], "modes_y": []})";
    QTest::newRow("array") << "[" + tool + "]" << QString();
    QTest::newRow("object") << R"({"name": "lib", "tools": [)" + tool + "]}" << QString();
    QTest::newRow("teeth") << QByteArray(R"([{"id": "A", "teeth": 0, "diameter_mm": 16, "helix_deg": 0,
        "modes_x": [], "modes_y": []}])")
                           << "tools[0].teeth = 0: must be an integer in [1, 100]";
    QTest::newRow("duplicate id") << "[" + tool + ", " + tool + "]"
                                  << R"(tools[1].id = "E": duplicate of tools[0].id (tool ids must be unique))";
    QTest::newRow("no tools") << QByteArray(R"({"name": "x"})") << "tools: missing (required array of tools)";
    QTest::newRow("tools not an array") << QByteArray(R"({"tools": 3})") << "tools: expected an array, got number";
    QTest::newRow("syntax") << QByteArray("[ ") << "JSON syntax error at offset 2: unterminated array";
  }
  void toolsFromJsonReadsALibrary() {
    QFETCH(QByteArray, json);
    QFETCH(QString, error);
    std::vector<ToolSpec> tools;
    QCOMPARE(projectFileErrorOf([&] { tools = toolsFromJson(json); }), error);
    if (!error.isEmpty()) return;
    QCOMPARE(tools.size(), std::size_t{1});
    QCOMPARE(tools[0].diameter_mm, 16.0);
    QCOMPARE(tools[0].modes_x[0].freq_Hz, 900.0);
    QCOMPARE(tools[0].unknown, (QJsonObject{{"x_shop", 7}}));
  }

  void saveReloadIsIdentical_data() {
    QTest::addColumn<QString>("path");
    QTest::newRow("rubio") << projectsPath("rubio2006-tool-selection.mxproj");
    QTest::newRow("insperger") << projectsPath("benchmark-insperger-1dof.mxproj");
    QTest::newRow("valid-full") << fixturePath("valid-full.mxproj");
    QTest::newRow("unknown-keys") << fixturePath("unknown-keys.mxproj");
  }

  void saveReloadIsIdentical() {
    QFETCH(QString, path);
    QTemporaryDir dir;
    const QString out = dir.filePath("saved.mxproj");
    const Project loaded = loadProject(path);
    saveProject(loaded, out);
    QCOMPARE(readJson(out), readJson(path));  // the file itself, unknown keys and all
    const Project reloaded = loadProject(out);
    QCOMPARE(projectToJson(reloaded), projectToJson(loaded));
    QCOMPARE(reloaded.document, loaded.document);
    QFile text(out);
    QVERIFY(text.open(QIODevice::ReadOnly));
    QVERIFY(text.readAll().startsWith("{\n  \"format\": \"millexpert-project\",\n  \"version\": 1,\n  \"name\": "));
  }

  void unknownKeysSurviveEdits() {
    Project p = loadProject(fixturePath("unknown-keys.mxproj"));
    p.machine->spindle_power_W = 800;
    p.tools[0].teeth = 4;
    p.tools[0].modes_x[0].damping_pct = 4.2;
    p.expert->grid->speed_step_rpm = 50;
    QTemporaryDir dir;
    const QString out = dir.filePath("edited.mxproj");
    saveProject(p, out);
    const QJsonObject j = readJson(out);
    QCOMPARE(j["x_root_note"].toString(), QString("kept at the root"));
    QCOMPARE(j["x_root_table"].toArray(), (QJsonArray{1, 2.5, QJsonObject{{"deep", true}}}));
    QCOMPARE(j["x_gui"].toObject()["last_tool"].toString(), QString("R1"));
    QCOMPARE(j["machine"].toObject()["x_machine_vendor"].toString(), QString("ACME"));
    QCOMPARE(j["machine"].toObject()["spindle_power_W"].toDouble(), 800.0);
    QCOMPARE(j["material"].toObject()["x_material_grade"].toString(), QString("6061-T6"));
    QVERIFY(j["operation"].toObject().contains("x_operation_coolant"));
    QVERIFY(j["operation"].toObject()["x_operation_coolant"].isNull());
    const QJsonObject tool = j["tools"].toArray()[0].toObject();
    QCOMPARE(tool["x_tool_holder"].toString(), QString("HSK63"));
    QCOMPARE(tool["teeth"].toDouble(), 4.0);
    const QJsonObject mode = tool["modes_x"].toArray()[0].toObject();
    QCOMPARE(mode["x_mode_source"].toString(), QString("tap test 12"));
    QCOMPARE(mode["damping_pct"].toDouble(), 4.2);
    QCOMPARE(mode["freq_Hz"].toDouble(), 603.0);
    const QJsonObject expert = j["expert"].toObject();
    QCOMPARE(expert["x_expert_comment"].toString(), QString("tuned"));
    QCOMPARE(expert["grid"].toObject()["x_grid_refine"].toDouble(), 2.0);
    QCOMPARE(expert["grid"].toObject()["speed_step_rpm"].toDouble(), 50.0);
    QVERIFY(!expert.contains("c"));  // defaults are not written out
    QCOMPARE(loadProject(out).tools[0].teeth, 4);
  }

  // operating_point at the edges of its ranges: the largest speed, depth and feed and the smallest
  // positive ones are read as they are.
  void operatingPointEdgeValues_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<double>("value");
    QTest::newRow("top speed") << "speed_rpm" << 1e5;
    QTest::newRow("slowest speed") << "speed_rpm" << 1e-3;
    QTest::newRow("deepest") << "depth_mm" << 1000.0;
    QTest::newRow("shallowest") << "depth_mm" << 1e-6;
    QTest::newRow("largest feed") << "feed_mm_per_tooth" << 10.0;
    QTest::newRow("smallest feed") << "feed_mm_per_tooth" << 1e-6;
  }
  void operatingPointEdgeValues() {
    QFETCH(QString, key);
    QFETCH(double, value);
    QJsonObject root = readJson(fixturePath("valid-full.mxproj"));
    QJsonObject point = root["operating_point"].toObject();
    point[key] = value;
    root["operating_point"] = point;
    const Project p = projectFromJson(root);
    QCOMPARE(projectToJson(p)["operating_point"].toObject()[key].toDouble(), value);
  }

  // operating_point: read, written after expert in the documented key order with an unknown key kept,
  // removed with that key; the round trip is exact.
  void operatingPointRoundTrip() {
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    const Project p = projectFromJson(mutated(base, {"operating_point/x_note=\"from the shop\""}));
    QVERIFY(p.operating_point);
    QCOMPARE(*p.operating_point, (OperatingPointSpec{"T1", 8000.0, 1.5, 0.1}));
    QTemporaryDir dir;
    const QString out = dir.filePath("point.mxproj");
    saveProject(p, out);
    const QByteArray text = readBytes(out);
    QVERIFY2(
        text.endsWith("  \"operating_point\": {\n    \"tool\": \"T1\",\n    \"speed_rpm\": 8000,\n"
                      "    \"depth_mm\": 1.5,\n    \"feed_mm_per_tooth\": 0.1,\n    \"x_note\": \"from the shop\"\n"
                      "  }\n}\n"),
        text.right(200).constData());
    QVERIFY(text.indexOf("\"expert\"") < text.indexOf("\"operating_point\""));
    const Project reloaded = loadProject(out);
    QCOMPARE(reloaded.operating_point, p.operating_point);
    QCOMPARE(projectToJson(reloaded), projectToJson(p));
    Project removed = p;
    removed.operating_point.reset();
    QVERIFY(!projectToJson(removed).contains("operating_point"));
    QVERIFY(!loadProject(fixturePath("unknown-keys.mxproj")).operating_point);  // optional
  }

  // machine.max_torque_Nm and machine.spindle_curve: read, written back, and a row's unknown key stays.
  void spindleLimitsRoundTrip() {
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    const QJsonObject root = mutated(base, {"machine/max_torque_Nm=9", "machine/x_spindle_maker=\"ACME\"",
                                            "machine/spindle_curve=[{\"speed_rpm\": 0, \"power_W\": 0}, "
                                            "{\"speed_rpm\": 1500, \"power_W\": 1413.7, \"x_gear\": \"low\"}]"});
    const Project p = projectFromJson(root);
    QCOMPARE(*p.machine->max_torque_Nm, 9.0);
    QCOMPARE(p.machine->spindle_curve->size(), std::size_t(2));
    QCOMPARE(p.machine->spindle_curve->at(1).speed_rpm, 1500.0);
    QCOMPARE(p.machine->spindle_curve->at(1).power_W, 1413.7);
    const QJsonObject machine = projectToJson(p)["machine"].toObject();
    QCOMPARE(machine["max_torque_Nm"].toDouble(), 9.0);
    QCOMPARE(machine["x_spindle_maker"].toString(), QString("ACME"));
    QCOMPARE(machine["spindle_curve"].toArray()[1].toObject()["x_gear"].toString(), QString("low"));
    QCOMPARE(projectFromJson(projectToJson(p)).machine, p.machine);
    Project removed = p;
    removed.machine->max_torque_Nm.reset();
    removed.machine->spindle_curve.reset();
    const QJsonObject without = projectToJson(removed)["machine"].toObject();
    QVERIFY(!without.contains("max_torque_Nm") && !without.contains("spindle_curve"));
  }

  // tools[].max_force_N: read, written back, removed; F_allow falls back to the control section's
  // safety_factor * breakage_force_N, and is unbounded without either.
  void toolForceLimitRoundTripAndFallback() {
    const QJsonObject base = readJson(fixturePath("valid-full.mxproj"));
    const Project p = projectFromJson(mutated(base, {"tools/0/max_force_N=450"}));
    QCOMPARE(*p.tools[0].max_force_N, 450.0);
    QVERIFY(!p.tools[1].max_force_N);
    QCOMPARE(projectToJson(p)["tools"].toArray()[0].toObject()["max_force_N"].toDouble(), 450.0);
    QCOMPARE(projectFromJson(projectToJson(p)).tools, p.tools);
    QCOMPARE(p.toolForceLimitN(p.tools[0]), 450.0);
    Project q = p;
    q.control.reset();
    QVERIFY(std::isinf(q.toolForceLimitN(q.tools[1])));
    q.control = ControlSection{};
    q.control->breakage_force_N = 2000.0;
    QCOMPARE(q.toolForceLimitN(q.tools[1]), 2000.0);  // safety factor 1 by default
    q.control->safety_factor = 0.4;
    QCOMPARE(q.toolForceLimitN(q.tools[1]), 800.0);
    QCOMPARE(q.toolForceLimitN(q.tools[0]), 450.0);  // the tool's own limit comes first
    q.control->breakage_force_N = 0.0;               // 0: not given
    QVERIFY(std::isinf(q.toolForceLimitN(q.tools[1])));
    q.tools[0].max_force_N.reset();
    QVERIFY(!projectToJson(q)["tools"].toArray()[0].toObject().contains("max_force_N"));
  }

  void structuralEditsOnSave() {
    Project p = loadProject(fixturePath("unknown-keys.mxproj"));
    p.tools[0].Kt_N_mm2 = 650.0;  // both coefficients on the tool: the material section is not needed
    p.tools[0].Kr = 0.25;
    ToolSpec added = p.tools[0];
    added.id = "R9";
    added.unknown = {};  // a new tool, not a copy: none of the file's keys
    added.modes_x[0].unknown = {};
    added.radial_depth_mm = 5.0;
    p.tools.push_back(added);
    p.operation->radial_immersion.reset();
    p.operation->radial_depth_mm = 12.0;
    p.machine->max_feed_mm_s = 40.0;
    p.expert->c = {0.1, 0.8, 0.1};
    p.material.reset();
    QJsonObject j = projectToJson(p);
    QJsonArray tools = j["tools"].toArray();
    QCOMPARE(tools.size(), 2);
    QVERIFY(!tools[1].toObject().contains("x_tool_holder"));
    QCOMPARE(tools[1].toObject()["radial_depth_mm"].toDouble(), 5.0);
    QVERIFY(!tools[1].toObject()["modes_x"].toArray()[0].toObject().contains("x_mode_source"));
    QCOMPARE(tools[0].toObject()["Kt_N_mm2"].toDouble(), 650.0);
    QVERIFY(!j.contains("material"));
    QVERIFY(!j["operation"].toObject().contains("radial_immersion"));
    QCOMPARE(j["operation"].toObject()["radial_depth_mm"].toDouble(), 12.0);
    QCOMPARE(j["machine"].toObject()["max_feed_mm_s"].toDouble(), 40.0);
    QCOMPARE(j["expert"].toObject()["c"].toArray(), (QJsonArray{0.1, 0.8, 0.1}));
    const Project back = projectFromJson(j);
    QCOMPARE(back.setupFor("R9").radial_depth_m, 0.005);
    QCOMPARE(back.setupFor("R1").tangential_coefficient_pa, 6.5e8);

    p.tools.erase(p.tools.begin());
    p.tools[0].Kt_N_mm2.reset();
    p.tools[0].Kr.reset();
    p.tools[0].modes_y.clear();
    j = projectToJson(p);
    tools = j["tools"].toArray();
    QCOMPARE(tools.size(), 1);
    QCOMPARE(tools[0].toObject()["id"].toString(), QString("R9"));
    QVERIFY(!tools[0].toObject().contains("Kt_N_mm2"));
    QCOMPARE(tools[0].toObject()["modes_y"].toArray(), QJsonArray());
    p.tools.clear();
    QCOMPARE(projectToJson(p)["tools"].toArray(), QJsonArray());
  }

  void numbersRoundTripExactly() {
    Project p = loadProject(fixturePath("valid-full.mxproj"));
    // Shortest round-trip texts, and the neighbours of the stiffness range's ends.
    const double awkward[] = {0.1 + 0.2, 1.3400496480507487, 1.0 / 3.0, std::nextafter(0.001, 1.0),
                              std::nextafter(1e6, 0.0)};
    QTemporaryDir dir;
    const QString out = dir.filePath("numbers.mxproj");
    for (double v : awkward) {
      p.tools[0].modes_x[1].stiffness_N_per_um = v;
      saveProject(p, out);
      const double back = loadProject(out).tools[0].modes_x[1].stiffness_N_per_um;
      QVERIFY2(back == v, qPrintable(QString::number(v, 'g', 17)));
    }
  }

  void saveIsAtomicAndReportsErrors() {
    QTemporaryDir dir;
    const QString out = dir.filePath("p.mxproj");
    const Project p = loadProject(fixturePath("valid-full.mxproj"));
    saveProject(p, out);
    saveProject(p, out);  // overwrite in place
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"p.mxproj"});
    const QString impossible = dir.filePath("no-such-dir/p.mxproj");
    expectContains(projectFileErrorOf([&] { saveProject(p, impossible); }), {impossible, "cannot write project file"});
  }
};

MX_REGISTER_TEST(TestProjectFile)
#include "test_project_file.moc"
