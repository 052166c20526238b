// The typed process sections (control, sdnrp, force_control, part_program, supervisor, pareto,
// operator_rules, expert extras): every example project saves byte-identically after a normalising
// save, typed edits reach the file, and the section ranges are checked when a project is loaded.
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

#include "document/project.h"
#include "services/control_request.h"
#include "services/sdnrp_request.h"
#include "support/project_files.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;
using namespace mx::test;

namespace {

QString sectionsErrorOf(const QJsonObject& root) {
  try {
    projectFromJson(root);
  } catch (const ProjectError& e) {
    return QString::fromStdString(e.what());
  }
  return {};
}

// The tools' FRF files as absolute paths: a save to another folder names the same files differently.
QJsonObject withAbsoluteFrfFiles(QJsonObject root, const QString& folder) {
  QJsonArray tools = root.value("tools").toArray();
  for (auto&& entry : tools) {
    QJsonObject tool = entry.toObject();
    for (const char* key : {"frf_x", "frf_y"}) {
      if (!tool.contains(key)) continue;
      QJsonObject ref = tool.value(key).toObject();
      ref["file"] = QDir::cleanPath(QDir(folder).absoluteFilePath(ref.value("file").toString()));
      tool[key] = ref;
    }
    entry = tool;
  }
  if (!tools.isEmpty()) root["tools"] = tools;
  return root;
}

QJsonObject minimalWith(const QString& section, const QJsonValue& value) {
  return QJsonObject{{"format", "millexpert-project"}, {"version", 1}, {"name", "x"}, {section, value}};
}

}  // namespace

class TestProjectSections : public QObject {
  Q_OBJECT

 private slots:
  void everyExampleSavesByteIdentically() {
    const QStringList names = QDir(MX_PROJECTS_DIR).entryList({"*.mxproj"}, QDir::Files, QDir::Name);
    QCOMPARE_GE(names.size(), 7);
    QTemporaryDir dir;
    for (const QString& name : names) {
      const QString first = dir.filePath(name + ".1");
      const QString second = dir.filePath(name + ".2");
      saveProject(loadProject(projectsPath(name)), first);
      // every key and value kept, the FRF paths naming the same files
      QCOMPARE(withAbsoluteFrfFiles(readJson(first), dir.path()),
               withAbsoluteFrfFiles(readJson(projectsPath(name)), MX_PROJECTS_DIR));
      saveProject(loadProject(first), second);
      QCOMPARE(readBytes(second), readBytes(first));
    }
  }

  void unknownKeysStayWithTheirTool() {
    auto tool = [](const QString& id, const QString& key, double value) {
      return QJsonObject{
          {"id", id},
          {"teeth", 2},
          {"diameter_mm", 10},
          {"helix_deg", 0},
          {key, value},
          {"modes_y", QJsonArray()},
          {"modes_x", QJsonArray{QJsonObject{
                          {"freq_Hz", 500}, {"damping_pct", 2}, {"stiffness_N_per_um", 5}, {"x_mode_of", id}}}}};
    };
    QJsonObject root = minimalWith("machine", QJsonObject{{"spindle_power_W", 1000}, {"x_vendor", "ACME"}});
    root.insert("tools", QJsonArray{tool("A", "x_a", 1), tool("B", "x_b", 2), tool("C", "x_c", 3)});
    Project p = projectFromJson(root);
    QCOMPARE(p.document, (QJsonObject{{"machine", QJsonObject{{"x_vendor", "ACME"}}}}));  // unknown keys only
    QCOMPARE(p.tools[1].unknown, (QJsonObject{{"x_b", 2}}));

    std::swap(p.tools[0], p.tools[2]);   // C, B, A
    p.tools.erase(p.tools.begin() + 1);  // C, A
    const QJsonArray tools = projectToJson(p).value("tools").toArray();
    QCOMPARE(tools.size(), 2);
    const QJsonObject first = tools[0].toObject(), second = tools[1].toObject();
    QCOMPARE(first.value("id").toString(), QString("C"));
    QCOMPARE(first.value("x_c").toDouble(), 3.0);
    QVERIFY(!first.contains("x_a") && !first.contains("x_b"));
    QCOMPARE(first.value("modes_x").toArray()[0].toObject().value("x_mode_of").toString(), QString("C"));
    QCOMPARE(second.value("id").toString(), QString("A"));
    QCOMPARE(second.value("x_a").toDouble(), 1.0);
    QVERIFY(!second.contains("x_b") && !second.contains("x_c"));
    QCOMPARE(second.value("modes_x").toArray()[0].toObject().value("x_mode_of").toString(), QString("A"));
    QCOMPARE(projectToJson(p).value("machine").toObject().value("x_vendor").toString(), QString("ACME"));
  }

  // The elements of the sections' arrays of objects keep their own unknown keys, like tools.
  void unknownKeysStayWithTheirElement_data() {
    QTest::addColumn<QString>("section");
    QTest::addColumn<QString>("array");
    QTest::addColumn<QString>("key");  // a typed number of each element
    QTest::newRow("control.workpiece") << "control"
                                       << "workpiece"
                                       << "length_mm";
    QTest::newRow("part_program.depth_profile") << "part_program"
                                                << "depth_profile"
                                                << "length_mm";
    QTest::newRow("supervisor.events") << "supervisor"
                                       << "events"
                                       << "t_s";
  }
  void unknownKeysStayWithTheirElement() {
    QFETCH(QString, section);
    QFETCH(QString, array);
    QFETCH(QString, key);
    auto element = [&](double value, const QString& unknown) {
      QJsonObject e = key == "t_s" ? QJsonObject{{"t_s", value}, {"type", "chatter"}}
                                   : QJsonObject{{"length_mm", value}, {"depth_mm", 1.5}};
      e.insert(unknown, value);
      return e;
    };
    QJsonObject body{{array, QJsonArray{element(10, "x_a"), element(20, "x_b"), element(30, "x_c")}}};
    if (section == "control") body.insert("spindle_rpm", 1000);
    QJsonObject root = minimalWith(section, body);
    root.insert("material", QJsonObject{{"name", "steel"}, {"Kt_N_mm2", 2000}, {"Kr", 0.3}});
    Project p = projectFromJson(root);
    QCOMPARE(projectToJson(p), root);
    QVERIFY(!p.document.contains(section));  // the elements hold them, not the document

    auto reorder = [](auto& list) {
      std::swap((*list)[0], (*list)[2]);  // 30, 20, 10
      list->erase(list->begin() + 1);     // 30, 10
    };
    if (section == "control") reorder(p.control->workpiece);
    if (section == "part_program") reorder(p.part_program->depth_profile);
    if (section == "supervisor") reorder(p.supervisor->events);
    const QJsonArray out = projectToJson(p).value(section).toObject().value(array).toArray();
    QCOMPARE(out.size(), 2);
    const QJsonObject first = out[0].toObject(), second = out[1].toObject();
    QCOMPARE(first.value(key).toDouble(), 30.0);
    QCOMPARE(first.value("x_c").toDouble(), 30.0);
    QVERIFY(!first.contains("x_a") && !first.contains("x_b"));
    QCOMPARE(second.value(key).toDouble(), 10.0);
    QCOMPARE(second.value("x_a").toDouble(), 10.0);
    QVERIFY(!second.contains("x_b") && !second.contains("x_c"));
  }

  // A sub-object the project no longer has takes its unknown keys with it; its parent keeps its own.
  void unknownKeysGoWithTheirSubObject() {
    const QJsonObject rls{{"lambda", 0.98}, {"x_tuned_by", "rls"}};
    const QJsonObject charts{{"x_layout", "grid"}, {"none", QJsonObject{{"steps", QJsonArray()}}}};
    const QJsonObject supervisor{{"x_cell", 4}, {"charts", charts}};
    QJsonObject root = minimalWith("control", QJsonObject{{"spindle_rpm", 700}, {"x_note", "n"}, {"rls", rls}});
    root.insert("material", QJsonObject{{"name", "steel"}, {"Kt_N_mm2", 2000}, {"Kr", 0.3}});
    root.insert("supervisor", supervisor);
    Project p = projectFromJson(root);
    QCOMPARE(p.document.value("control").toObject(),
             (QJsonObject{{"x_note", "n"}, {"rls", QJsonObject{{"x_tuned_by", "rls"}}}}));
    p.control->rls.reset();
    p.supervisor->charts.reset();
    const QJsonObject j = projectToJson(p);
    QCOMPARE(j.value("control").toObject(), (QJsonObject{{"spindle_rpm", 700}, {"x_note", "n"}}));
    QCOMPARE(j.value("supervisor").toObject(), (QJsonObject{{"x_cell", 4}}));
    p.supervisor.reset();
    QVERIFY(!projectToJson(p).contains("supervisor"));
  }

  void sectionsAreTyped() {
    const Project c = loadProject(projectsPath("rubio2006-adaptive-control.mxproj"));
    QVERIFY(c.control);
    QCOMPARE(*c.control->spindle_rpm, 715.0);
    QCOMPARE(*c.control->beta, -0.3);
    const Project s = loadProject(projectsPath("cus-zuperl-sdnrp.mxproj"));
    QVERIFY(s.sdnrp && s.force_control && s.part_program);
    QCOMPARE(*s.sdnrp->initial->feed_mm_min, 430.41);
    QCOMPARE(*s.force_control->reference_force_N, 250.0);
    QCOMPARE(*s.part_program->controller, QString("model-based"));
    const Project l = loadProject(projectsPath("landers-face-milling.mxproj"));
    QVERIFY(l.supervisor && l.supervisor->passes_mm);
    QCOMPARE(l.supervisor->passes_mm->smc1->size(), std::size_t{2});
    const Project r = loadProject(projectsPath("rubio-pareto-case.mxproj"));
    QVERIFY(r.pareto && r.pareto->taylor);
    QCOMPARE(r.pareto->taylor->K, 15300000.0);
    QCOMPARE(*r.pareto->normalisation, QString("log"));
    QCOMPARE(*r.pareto->objective, QString("weighted"));
    QCOMPARE(r.pareto->economics->tool_change_min, 2.0);
    QCOMPARE(*r.pareto->requirements->min_mrr_fraction, 0.25);
  }

  // control.programme, sample_period and rule4_periods: typed, mapped to one workpiece step per point with its
  // spindle speed (Pareto paper, Fig. 6), and written back unchanged.
  void controlProgrammeIsTypedAndMapped() {
    const Project p = loadProject(projectsPath("rubio-pareto-case.mxproj"));
    QVERIFY(p.control && p.control->programme);
    QCOMPARE(p.control->programme->size(), std::size_t{3});
    QCOMPARE(*p.control->sample_period, QString("rule4"));
    QCOMPARE(*p.control->rule4_periods, 4.0);
    QCOMPARE((*p.control->programme)[2].depth_mm, 1.5124);
    QCOMPARE(*(*p.control->programme)[1].feed_mm_s, 5.58);
    const ControlRequest r = controlRequestFromProject(p);
    QVERIFY(r.programme);
    QCOMPARE(r.settings.sample_period, SamplePeriodRule::Rule4);
    QCOMPARE(r.settings.rule4_periods, 4);
    QCOMPARE(r.settings.force_reference_N, 600.0);
    QCOMPARE(r.settings.process.spindle_rev_s, 30.0);  // the first point
    QCOMPARE(r.settings.workpiece.steps.size(), std::size_t{3});
    QCOMPARE(r.settings.workpiece.steps[1].spindle_rev_s, 2412.0 / 60.0);
    QCOMPARE(r.settings.workpiece.steps[2].length_m, 1.0);
    QCOMPARE(*r.programmed_feed_m_s[2], 17.96e-3);
    const Project back = projectFromJson(projectToJson(p));
    QVERIFY(*back.control == *p.control);
    const ControlSection written = controlSectionFrom(r, *p.control);
    QVERIFY(!written.workpiece && written.programme);
    for (std::size_t i = 0; i < 3; ++i) {
      const ControlProgrammePointSpec &a = (*written.programme)[i], &b = (*p.control->programme)[i];
      QVERIFY(std::abs(a.speed_rpm - b.speed_rpm) < 1e-9 && std::abs(a.depth_mm - b.depth_mm) < 1e-12);
      QVERIFY(std::abs(a.length_mm - b.length_mm) < 1e-9 && a.feed_mm_s == b.feed_mm_s);
    }
    QCOMPARE(*written.sample_period, QString("rule4"));
    // the defaults: spindle period, k = 4
    const Project d = loadProject(projectsPath("rubio2006-adaptive-control.mxproj"));
    QCOMPARE(controlRequestFromProject(d).settings.sample_period, SamplePeriodRule::Spindle);
    QCOMPARE(controlRequestFromProject(d).settings.rule4_periods, 4);
    QVERIFY(!controlRequestFromProject(d).programme);
  }

  void typedEditsReachTheFile() {
    Project p = loadProject(projectsPath("rubio2006-adaptive-control.mxproj"));
    p.control->beta = 0.4;
    p.control->rls->lambda.reset();
    p.operator_rules = QStringList{"if tool.diameter_mm < 10 then speed_rpm <= 8000"};
    const QJsonObject json = projectToJson(p);
    QCOMPARE(json.value("control").toObject().value("beta").toDouble(), 0.4);
    QVERIFY(!json.value("control").toObject().value("rls").toObject().contains("lambda"));
    QCOMPARE(json.value("operator_rules").toArray().size(), 1);
    const Project back = projectFromJson(json);
    QCOMPARE(controlRequestFromProject(back).settings.beta, 0.4);
    QCOMPARE(controlRequestFromProject(back).settings.rls.forgetting_factor, 1.0);  // the default
  }

  void defaultsAreNotWritten() {
    const QJsonObject root = minimalWith("sdnrp", QJsonObject{{"ra_um", 1.2}});
    const Project p = projectFromJson(root);
    QCOMPARE(projectToJson(p).value("sdnrp").toObject(), (QJsonObject{{"ra_um", 1.2}}));
    const SdnrpSettings s = sdnrpSettingsFromProject(p);
    QCOMPARE(s.ra_desired_m, 1.2e-6);
    QCOMPARE(s.duration_s, 15.0);
  }

  void rangesAreCheckedOnLoad_data() {
    QTest::addColumn<QString>("section");
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("message");
    QTest::newRow("sdnrp.ra_um") << "sdnrp"
                                 << R"({"ra_um": 9})"
                                 << "sdnrp.ra_um = 9: must be in [0.25, 2.5]";
    QTest::newRow("seed") << "sdnrp"
                          << R"({"disturbance": {"seed": 1.5}})"
                          << "sdnrp.disturbance.seed = 1.5: must be an integer in [0, 9e15]";
    QTest::newRow("control.beta") << "control"
                                  << R"({"spindle_rpm": 700, "cutting_pressure_N_mm2": 1, "beta": 2})"
                                  << "control.beta = 2: must be in [-1, 1]";
    QTest::newRow("control.spindle_rpm") << "control"
                                         << R"({"cutting_pressure_N_mm2": 1})"
                                         << "control.spindle_rpm is missing: must be in (0, 100000]";
    QTest::newRow("rls.reset") << "control"
                               << R"({"spindle_rpm": 7, "cutting_pressure_N_mm2": 1, "rls": {"reset": "x"}})"
                               << "control.rls.reset = 'x': must be one of error, trace, none";
    QTest::newRow("workpiece")
        << "control"
        << R"({"spindle_rpm": 7, "cutting_pressure_N_mm2": 1, "workpiece": [{"length_mm": 0, "depth_mm": 1}]})"
        << "control.workpiece[0].length_mm = 0: must be in (0, 1e7]";
    QTest::newRow("sample_period foo") << "control"
                                       << R"({"spindle_rpm": 7, "cutting_pressure_N_mm2": 1, "sample_period": "foo"})"
                                       << "control.sample_period = 'foo': must be one of spindle, rule4";
    QTest::newRow("rule4_periods 0") << "control"
                                     << R"({"spindle_rpm": 7, "cutting_pressure_N_mm2": 1, "rule4_periods": 0})"
                                     << "control.rule4_periods = 0: must be an integer in [1, 100]";
    QTest::newRow("rule4_periods 101") << "control"
                                       << R"({"spindle_rpm": 7, "cutting_pressure_N_mm2": 1, "rule4_periods": 101})"
                                       << "control.rule4_periods = 101: must be an integer in [1, 100]";
    QTest::newRow("rule4_periods 1.5") << "control"
                                       << R"({"spindle_rpm": 7, "cutting_pressure_N_mm2": 1, "rule4_periods": 1.5})"
                                       << "control.rule4_periods = 1.5: must be an integer in [1, 100]";
    QTest::newRow("programme depth")
        << "control"
        << R"({"cutting_pressure_N_mm2": 1, "programme": [{"speed_rpm": 1800, "depth_mm": 0, "length_mm": 1}]})"
        << "control.programme[0].depth_mm = 0: must be in (0, 1000]";
    QTest::newRow("programme length missing")
        << "control"
        << R"({"cutting_pressure_N_mm2": 1, "programme": [{"speed_rpm": 1800, "depth_mm": 1}]})"
        << "control.programme[0].length_mm is missing: must be in (0, 1e7]";
    QTest::newRow("programme empty") << "control"
                                     << R"({"cutting_pressure_N_mm2": 1, "programme": []})"
                                     << "control.programme = (not a non-empty array): must be an array of "
                                        "{speed_rpm, depth_mm, length_mm[, feed_mm_s]}";
    QTest::newRow("passes") << "supervisor"
                            << R"({"passes_mm": {"smc1": [1, 30]}})"
                            << "supervisor.passes_mm.smc1[1] = 30: must be a depth in (0, 20] mm";
    QTest::newRow("event") << "supervisor"
                           << R"({"events": [{"t_s": 1, "type": "boom"}]})"
                           << "supervisor.events[0].type = 'boom': must be one of feed_hold_on, feed_hold_off, chatter";
    QTest::newRow("force model") << "force_control"
                                 << R"({"model": {"K_N": -1}})"
                                 << "force_control.model.K_N = -1: must be in (0, 1e9]";
    QTest::newRow("controller") << "part_program"
                                << R"({"controller": "pid"})"
                                << "part_program.controller = 'pid': must be adaptive or model-based";
    QTest::newRow("pareto.taylor") << "pareto"
                                   << R"({})"
                                   << "pareto.taylor is missing: the model constants K and exponents";
    const QString models = R"("taylor": {"K": 1, "speed_exponent": -3, "depth_exponent": -1, "feed_exponent": -1},
        "roughness": {"K": 1, "speed_exponent": 0.4, "depth_exponent": 1, "feed_exponent": 0.4})";
    QTest::newRow("max_time without a volume")
        << "pareto"
        << "{" + models + R"(, "requirements": {"max_time_min": 5}})"
        << "pareto.requirements.max_time_min needs a removal volume: pareto.requirements.removal_volume_cm3 or "
           "pareto.economics.removal_volume_cm3";
    QTest::newRow("economics field missing") << "pareto"
                                             << "{" + models + R"(, "economics": {"machine_rate_per_h": 60}})"
                                             << "pareto.economics.tool_cost is missing: must be in [0, 1e6]";
    QTest::newRow("rate and tool cost zero")
        << "pareto"
        << "{" + models +
               R"(, "economics": {"machine_rate_per_h": 0, "tool_cost": 0, "tool_change_min": 1, "removal_volume_cm3": 1}})"
        << "pareto.economics: machine_rate_per_h = 0 and tool_cost = 0: at least one must be > 0";
    QTest::newRow("time") << "pareto"
                          << "{" + models + R"(, "requirements": {"max_time_min": 0, "removal_volume_cm3": 1}})"
                          << "pareto.requirements.max_time_min = 0: must be in (0, 1e6]";
  }

  void rangesAreCheckedOnLoad() {
    QFETCH(QString, section);
    QFETCH(QString, json);
    QFETCH(QString, message);
    const QJsonObject value = QJsonDocument::fromJson(json.toUtf8()).object();
    QCOMPARE(sectionsErrorOf(minimalWith(section, value)), message);
  }

  void controlEngagementIsTheEngineImmersion() {
    Project p = loadProject(projectsPath("rubio2006-adaptive-control.mxproj"));
    p.control->start_angle_deg.reset();
    p.control->exit_angle_deg.reset();
    p.operation->milling = MillingDirection::Up;
    p.operation->radial_immersion = 0.5;
    p.operation->radial_depth_mm.reset();
    const double deg = std::numbers::pi / 180.0;
    CuttingProcess c = controlRequestFromProject(p).settings.process;
    QCOMPARE(c.start_angle_rad, 0.0);
    QVERIFY(std::abs(c.exit_angle_rad - 90.0 * deg) < 1e-12);
    // The tool's own radial depth wins over the operation's, as in the stability model.
    p.tools[0].radial_depth_mm = 0.25 * p.tools[0].diameter_mm;
    c = controlRequestFromProject(p).settings.process;
    QVERIFY(std::abs(c.exit_angle_rad - 60.0 * deg) < 1e-12);
    p.operation->milling = MillingDirection::Down;
    c = controlRequestFromProject(p).settings.process;
    QVERIFY(std::abs(c.start_angle_rad - 120.0 * deg) < 1e-12);
    QVERIFY(std::abs(c.exit_angle_rad - 180.0 * deg) < 1e-12);
    const Immersion im = p.setupFor(p.tools[0].id).immersion;
    QCOMPARE(c.start_angle_rad, im.entry_rad);
    QCOMPARE(c.exit_angle_rad, im.exit_rad);
  }

  void reportedChatterIsChecked_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("json");
    QTest::addColumn<QString>("message");  // empty: accepted
    QTest::newRow("valid") << "reported_chatter"
                           << R"([{"tool": "R1", "speed_rpm": 5800, "depth_mm": 0.5}])"
                           << "";
    QTest::newRow("unknown tool") << "reported_chatter"
                                  << R"([{"tool": "R7", "speed_rpm": 5800, "depth_mm": 0.5}])"
                                  << "expert.reported_chatter[0].tool = 'R7': must be the id of a tool of the project";
    QTest::newRow("zero speed") << "reported_chatter"
                                << R"([{"tool": "R1", "speed_rpm": 0, "depth_mm": 0.5}])"
                                << "expert.reported_chatter[0].speed_rpm = 0: must be in [0.001, 1e6]";
    QTest::newRow("huge depth") << "reported_chatter"
                                << R"([{"tool": "R1", "speed_rpm": 5800, "depth_mm": 5000}])"
                                << "expert.reported_chatter[0].depth_mm = 5000: must be in [1e-6, 1000]";
    QTest::newRow("missing depth") << "reported_chatter"
                                   << R"([{"tool": "R1", "speed_rpm": 5800}])"
                                   << "expert.reported_chatter[0].depth_mm: missing (required number > 0)";
    QTest::newRow("negative frequency") << "reported_chatter"
                                        << R"([{"tool": "R1", "speed_rpm": 5800, "depth_mm": 0.5, "freq_Hz": -3}])"
                                        << "expert.reported_chatter[0].freq_Hz = -3: must be in [0.001, 1e6]";
    QTest::newRow("not an array") << "reported_chatter"
                                  << R"({"tool": "R1"})"
                                  << "expert.reported_chatter: expected an array, got object";
    QTest::newRow("bound negative") << "max_malfunction_iterations"
                                    << "-1"
                                    << "expert.max_malfunction_iterations = -1: must be an integer in [0, 10000]";
    QTest::newRow("bound fractional") << "max_malfunction_iterations"
                                      << "2.5"
                                      << "expert.max_malfunction_iterations = 2.5: must be an integer in [0, 10000]";
    QTest::newRow("bound zero") << "max_malfunction_iterations"
                                << "0"
                                << "";
  }
  void reportedChatterIsChecked() {
    QFETCH(QString, key);
    QFETCH(QString, json);
    QFETCH(QString, message);
    QJsonObject root = readJson(projectsPath("rubio2006-tool-selection.mxproj"));
    QJsonObject expert = root["expert"].toObject();
    expert[key] = QJsonDocument::fromJson(("{\"v\": " + json + "}").toUtf8()).object()["v"];
    root["expert"] = expert;
    QCOMPARE(sectionsErrorOf(root), message);
  }

  // The reports are typed, written back in order, and a row keeps the keys this build does not know.
  void reportedChatterRoundTrips() {
    QJsonObject root = readJson(projectsPath("rubio2006-tool-selection.mxproj"));
    QJsonObject expert = root["expert"].toObject();
    expert["reported_chatter"] = QJsonArray{
        QJsonObject{{"tool", "R2"}, {"speed_rpm", 4000}, {"depth_mm", 0.2}, {"freq_Hz", 950.5}, {"heard_by", "Ana"}},
        QJsonObject{{"tool", "R1"}, {"speed_rpm", 5800}, {"depth_mm", 0.5}}};
    expert["max_malfunction_iterations"] = 50;
    root["expert"] = expert;
    const Project p = projectFromJson(root);
    QCOMPARE(p.expert->reported_chatter.size(), std::size_t(2));
    QCOMPARE(p.expert->reported_chatter[0].tool, QString("R2"));
    QCOMPARE(*p.expert->reported_chatter[0].freq_Hz, 950.5);
    QVERIFY(!p.expert->reported_chatter[1].freq_Hz);
    QCOMPARE(*p.expert->max_malfunction_iterations, 50);
    const QJsonObject written = projectToJson(p);
    const QJsonArray rows = written["expert"].toObject()["reported_chatter"].toArray();
    QCOMPARE(rows[0].toObject()["heard_by"].toString(), QString("Ana"));
    QCOMPARE(rows[1].toObject()["speed_rpm"].toDouble(), 5800.0);
    QVERIFY(projectFromJson(written).expert == p.expert);
  }

  void expertExtrasAreChecked() {
    QJsonObject expert{{"delta_per_s", 0.0}, {"alpha", 1.0}, {"method", "fem"}};
    QCOMPARE(sectionsErrorOf(minimalWith("expert", expert)), QString("expert.method = 'fem': must be zoa or sdm"));
    expert.insert("method", "sdm");
    expert.insert("simulated_points", 0);
    QCOMPARE(sectionsErrorOf(minimalWith("expert", expert)),
             QString("expert.simulated_points = 0: must be an integer in [1, 1000]"));
    expert.insert("simulated_points", 20);
    const Project p = projectFromJson(minimalWith("expert", expert));
    QCOMPARE(*p.expert->simulated_points, 20);
    QCOMPARE(*p.expert->method, QString("sdm"));
    QVERIFY(!p.expert->rule5_search);
  }

  // expert.rule5_search: optional steps and iteration limit, checked and written back.
  void expertRule5Search() {
    QJsonObject expert{{"delta_per_s", 0.0}, {"alpha", 1.0}};
    expert.insert("rule5_search", QJsonObject{{"speed_step_rpm", 0.0}});
    QCOMPARE(sectionsErrorOf(minimalWith("expert", expert)),
             QString("expert.rule5_search.speed_step_rpm = 0: must be in (0, 1e5]"));
    expert.insert("rule5_search", QJsonObject{{"max_iterations", 2.5}});
    QCOMPARE(sectionsErrorOf(minimalWith("expert", expert)),
             QString("expert.rule5_search.max_iterations = 2.5: must be an integer in [0, 1000]"));
    expert.insert("rule5_search", QJsonObject{{"speed_step_rpm", 100.0},
                                              {"depth_step_mm", 0.02},
                                              {"feed_step_mm", 0.004},
                                              {"max_iterations", 7},
                                              {"future_key", 1}});
    const Project p = projectFromJson(minimalWith("expert", expert));
    QVERIFY(p.expert->rule5_search);
    const Rule5SearchSpec& s = *p.expert->rule5_search;
    QCOMPARE(*s.speed_step_rpm, 100.0);
    QCOMPARE(*s.depth_step_mm, 0.02);
    QCOMPARE(*s.feed_step_mm, 0.004);
    QCOMPARE(*s.max_iterations, 7);
    const QJsonObject written = projectToJson(p).value("expert").toObject().value("rule5_search").toObject();
    QCOMPARE(written.value("max_iterations").toInt(), 7);
    QCOMPARE(written.value("future_key").toInt(), 1);  // unknown keys survive
    QVERIFY(*projectFromJson(projectToJson(p)).expert == *p.expert);
  }
};

MX_REGISTER_TEST(TestProjectSections)
#include "test_project_sections.moc"
