// Grafcet charts in the project's JSON: round trip, defaults, keys of the editor kept per
// element, structure checked when the project loads, and every error naming its JSON path
// (structure errors and validation issues, receptivity errors with line and column).
#include <QJsonArray>
#include <QJsonDocument>

#include "document/project.h"
#include "document/project_grafcet_io.h"
#include "grafcet/grafcet_interpreter.h"
#include "test_registry.h"

using namespace mx;
using namespace mx::app;

namespace {

const char* kSmc1 = R"({"name": "SMC I",
 "steps": [
  {"id": 1, "name": "Initialize Modules", "initial": true, "actions": ["L*"]},
  {"id": 2, "name": "No Contact and No Chatter", "actions": ["A", "B", "I", "J"]},
  {"id": 3, "name": "Reset Modules", "actions": ["A", "B", "I", "J", "L*"]},
  {"id": 4, "name": "Contact and No Chatter", "actions": ["A", "B", "I", "J", "L"]},
  {"id": 5, "name": "Operator Feed Hold Active", "actions": ["A", "B", "C"]}],
 "transitions": [
  {"id": 1, "from": [1], "to": [2], "receptivity": "true"},
  {"id": 2, "from": [2], "to": [5], "receptivity": "a", "priority": 1},
  {"id": 3, "from": [2], "to": [3], "receptivity": "b", "priority": 2},
  {"id": 4, "from": [3], "to": [4], "receptivity": "true"},
  {"id": 5, "from": [4], "to": [5], "receptivity": "a", "priority": 1},
  {"id": 6, "from": [4], "to": [2], "receptivity": "b'", "priority": 2},
  {"id": 7, "from": [5], "to": [2], "receptivity": "a'"}]})";

QJsonObject parse(const char* text) {
  return QJsonDocument::fromJson(text).object();
}

// Reads and checks, as the project load and the supervised run do.
GrafcetChart loadChart(const QJsonValue& v, const QString& path, const std::optional<std::set<std::string>>& known) {
  GrafcetChart chart = grafcetChartFromJson(v, path).chart;
  checkGrafcetChart(chart, path, known);
  return chart;
}

QString grafcetErrorOf(const QJsonValue& v, const std::optional<std::set<std::string>>& known = std::nullopt) {
  try {
    loadChart(v, "supervisor.charts.smc1", known);
  } catch (const ProjectError& e) {
    if (e.exitCode() != 2) return "wrong exit code";
    return QString::fromStdString(e.what());
  }
  return {};
}

}  // namespace

class TestGrafcetJson : public QObject {
  Q_OBJECT
 private slots:
  void readsTheFormat() {
    const GrafcetChart c = loadChart(parse(kSmc1), "chart", std::set<std::string>{"a", "b"});
    QCOMPARE(c.name, std::string("SMC I"));
    QCOMPARE(c.steps.size(), std::size_t(5));
    QVERIFY(c.steps[0].initial);
    QVERIFY(!c.steps[1].initial);
    QCOMPARE(c.steps[2].actions, (std::vector<std::string>{"A", "B", "I", "J", "L*"}));
    QCOMPARE(c.transitions[5].receptivity, std::string("b'"));
    QCOMPARE(c.transitions[2].priority, 2);
    QCOMPARE(c.transitions[0].priority, 1);  // default
    QCOMPARE(c.transitions[6].from, std::vector<int>{5});
    // It runs: contact from state 2 -> state 4 with L reset.
    GrafcetInterpreter g(c);
    g.scan({});
    const ScanOutput o = g.scan({{"b", 1}});
    QCOMPARE(g.activeStepIds(), std::vector<int>{4});
    QCOMPARE(o.impulse_actions, std::vector<std::string>{"L*"});
  }

  void roundTrip() {
    const QJsonObject original = parse(kSmc1);
    const GrafcetChart c = grafcetChartFromJson(original, "chart").chart;
    const QJsonObject written = grafcetChartToJson(GrafcetChartSpec{c, {}, {}, {}});
    const GrafcetChartSpec backSpec = grafcetChartFromJson(written, "chart");
    const GrafcetChart& back = backSpec.chart;
    QCOMPARE(back.name, c.name);
    QCOMPARE(back.steps.size(), c.steps.size());
    for (std::size_t i = 0; i < c.steps.size(); ++i) {
      QCOMPARE(back.steps[i].id, c.steps[i].id);
      QCOMPARE(back.steps[i].name, c.steps[i].name);
      QCOMPARE(back.steps[i].initial, c.steps[i].initial);
      QCOMPARE(back.steps[i].actions, c.steps[i].actions);
    }
    QCOMPARE(back.transitions.size(), c.transitions.size());
    for (std::size_t i = 0; i < c.transitions.size(); ++i) {
      QCOMPARE(back.transitions[i].id, c.transitions[i].id);
      QCOMPARE(back.transitions[i].from, c.transitions[i].from);
      QCOMPARE(back.transitions[i].to, c.transitions[i].to);
      QCOMPARE(back.transitions[i].receptivity, c.transitions[i].receptivity);
      QCOMPARE(back.transitions[i].priority, c.transitions[i].priority);
    }
    // Writing again gives the same JSON; "initial" only where true, "priority" only where not 1.
    QCOMPARE(grafcetChartToJson(backSpec), written);
    QVERIFY(!written["steps"].toArray()[1].toObject().contains("initial"));
    QVERIFY(!written["transitions"].toArray()[1].toObject().contains("priority"));
    QCOMPARE(written["transitions"].toArray()[2].toObject()["priority"].toInt(), 2);
  }

  void keepsUnknownKeysOfThePrevious() {
    QJsonObject original = parse(kSmc1);
    original["layout"] = "vertical";
    QJsonArray steps = original["steps"].toArray();
    QJsonObject s2 = steps[1].toObject();
    s2["x"] = 120;
    steps[1] = s2;
    original["steps"] = steps;
    const GrafcetChartSpec read = grafcetChartFromJson(original, "chart");
    QCOMPARE(grafcetChartToJson(read), original);  // every key and value kept
    GrafcetChart c = read.chart;
    c.steps[1].name = "Renamed";
    const QJsonObject written = grafcetChartToJson(grafcetChartSpecWith(read, c));
    QCOMPARE(written["layout"].toString(), QString("vertical"));
    QCOMPARE(written["steps"].toArray()[1].toObject()["x"].toInt(), 120);
    QCOMPARE(written["steps"].toArray()[1].toObject()["name"].toString(), QString("Renamed"));
  }

  // The editor's chart comes back without the file's extra keys: they follow their step by id when
  // steps are deleted or reordered, and land on no other step.
  void unknownKeysStayWithTheirStep() {
    QJsonObject original = parse(kSmc1);
    QJsonArray steps = original["steps"].toArray();
    for (int i = 0; i < 5; ++i) {
      QJsonObject s = steps[i].toObject();
      s["x"] = 100 * (i + 1);
      steps[i] = s;
    }
    original["steps"] = steps;
    QJsonArray transitions = original["transitions"].toArray();
    QJsonObject t7 = transitions[6].toObject();
    t7["route"] = "left";
    transitions[6] = t7;
    original["transitions"] = transitions;
    const GrafcetChartSpec read = grafcetChartFromJson(original, "chart");

    GrafcetChart c = read.chart;
    std::swap(c.steps[0], c.steps[4]);              // 5, 2, 3, 4, 1
    c.steps.erase(c.steps.begin() + 1);             // 5, 3, 4, 1
    c.steps.push_back({9, "New", false, {}});       // 5, 3, 4, 1, 9
    std::swap(c.transitions[0], c.transitions[6]);  // 7, 2, ..., 1
    const QJsonObject written = grafcetChartToJson(grafcetChartSpecWith(read, c));
    const QJsonArray out = written["steps"].toArray();
    QCOMPARE(out.size(), 5);
    const std::vector<std::pair<int, int>> idAndX{{5, 500}, {3, 300}, {4, 400}, {1, 100}};
    for (qsizetype i = 0; i < 4; ++i) {
      QCOMPARE(out[i].toObject()["id"].toInt(), idAndX[static_cast<std::size_t>(i)].first);
      QCOMPARE(out[i].toObject()["x"].toInt(), idAndX[static_cast<std::size_t>(i)].second);
    }
    QVERIFY(!out[4].toObject().contains("x"));
    QCOMPARE(out[4].toObject().keys(), (QStringList{"id", "name"}));  // no defaults written
    const QJsonArray outT = written["transitions"].toArray();
    QCOMPARE(outT[0].toObject()["id"].toInt(), 7);
    QCOMPARE(outT[0].toObject()["route"].toString(), QString("left"));
    QVERIFY(!outT[6].toObject().contains("route"));
  }

  // Optional keys the file wrote at their default stay; those it left out stay out.
  void optionalKeysKeepTheirPresence() {
    const QJsonObject chart{
        {"name", ""},
        {"steps", QJsonArray{QJsonObject{{"id", 1}, {"name", "S1"}, {"initial", true}},
                             QJsonObject{{"id", 2}, {"name", "S2"}, {"initial", false}, {"actions", QJsonArray()}}}},
        {"transitions",
         QJsonArray{
             QJsonObject{{"id", 1}, {"from", QJsonArray{1}}, {"to", QJsonArray{2}}, {"receptivity", "a"}},
             QJsonObject{
                 {"id", 2}, {"from", QJsonArray{2}}, {"to", QJsonArray{1}}, {"receptivity", "a'"}, {"priority", 1}}}}};
    const GrafcetChartSpec read = grafcetChartFromJson(chart, "c");
    QCOMPARE(grafcetChartToJson(read), chart);
    QCOMPARE(read.steps[1].defaults_written, (QStringList{"initial", "actions"}));
    QCOMPARE(read.transitions[1].defaults_written, QStringList{"priority"});
    QVERIFY(read.transitions[0].defaults_written.isEmpty());
    const QJsonObject bare{{"steps", QJsonArray{QJsonObject{{"id", 1}, {"name", "S1"}, {"initial", true}}}}};
    QCOMPARE(grafcetChartToJson(grafcetChartFromJson(bare, "c")), bare);
  }

  // A project's charts are read when it loads: structure errors name the chart's field path, the
  // value and the range; content errors (an unknown signal) wait for the run of that controller.
  void chartsAreReadWithTheProject_data() {
    QTest::addColumn<QString>("step");  // the JSON of supervisor.charts.smc2.steps[0]
    QTest::addColumn<QString>("error");
    const QString p = "supervisor.charts.smc2.steps[0]";
    QTest::newRow("id negative") << R"({"id": -1, "name": "S"})"
                                 << p + ".id = -1: must be an integer in [0, 1000000000]";
    QTest::newRow("id too large") << R"({"id": 1000000001, "name": "S"})"
                                  << p + ".id = 1000000001: must be an integer in [0, 1000000000]";
    QTest::newRow("id fractional") << R"({"id": 2.5, "name": "S"})"
                                   << p + ".id = 2.5: must be an integer in [0, 1000000000]";
    QTest::newRow("name a number") << R"({"id": 1, "name": 4})" << p + ".name = 4: must be a string";
    QTest::newRow("initial a string") << R"({"id": 1, "name": "S", "initial": "yes"})"
                                      << p + ".initial = \"yes\": must be true or false";
  }
  void chartsAreReadWithTheProject() {
    QFETCH(QString, step);
    QFETCH(QString, error);
    const QJsonObject s = QJsonDocument::fromJson(step.toUtf8()).object();
    const QJsonObject chart{{"steps", QJsonArray{s}}};
    const QJsonObject root{{"format", "millexpert-project"},
                           {"version", 1},
                           {"name", "x"},
                           {"supervisor", QJsonObject{{"charts", QJsonObject{{"smc2", chart}}}}}};
    QString got;
    try {
      projectFromJson(root);
    } catch (const ProjectError& e) {
      got = QString::fromStdString(e.what());
    }
    QCOMPARE(got, error);
  }

  void projectHoldsTheTypedCharts() {
    const QJsonObject receptive{{"id", 1}, {"from", QJsonArray{1}}, {"to", QJsonArray{1}}, {"receptivity", "z"}};
    const QJsonObject chart{{"steps", QJsonArray{QJsonObject{{"id", 1}, {"name", "S"}, {"initial", true}}}},
                            {"transitions", QJsonArray{receptive}},
                            {"x_zoom", 2}};
    const QJsonObject charts{{"smc1", chart}, {"x_custom", QJsonObject{{"steps", 3}}}};
    const QJsonObject root{{"format", "millexpert-project"},
                           {"version", 1},
                           {"name", "x"},
                           {"supervisor", QJsonObject{{"charts", charts}}}};
    const Project p = projectFromJson(root);  // the unknown signal 'z' is the run's concern
    QVERIFY(p.supervisor->charts->smc1 && !p.supervisor->charts->none && !p.supervisor->charts->smc2);
    QCOMPARE(p.supervisor->charts->smc1->chart.transitions[0].receptivity, std::string("z"));
    QCOMPARE(p.supervisor->charts->smc1->keys.unknown, (QJsonObject{{"x_zoom", 2}}));
    QCOMPARE(projectToJson(p), root);  // a key of charts that is no controller is kept too
  }

  void errorsNameTheJsonPath_data() {
    QTest::addColumn<QString>("pointer");  // what to change: "<list>/<index>/<key>" or "<key>"
    QTest::addColumn<QString>("json");     // the new value, as JSON (empty: remove the key)
    QTest::addColumn<QString>("error");
    const QString p = "supervisor.charts.smc1";
    QTest::newRow("receptivity syntax") << "transitions/3/receptivity"
                                        << "\"(a b\""
                                        << p + ".transitions[3].receptivity: line 1, column 4: expected ')'";
    QTest::newRow("unknown signal") << "transitions/6/receptivity"
                                    << "\"z'\"" << p + ".transitions[6].receptivity: unknown signal 'z'";
    QTest::newRow("no source") << "transitions/2/from"
                               << "[]" << p + ".transitions[2].from: the transition has no source step";
    QTest::newRow("no target") << "transitions/2/to"
                               << "[]" << p + ".transitions[2].to: the transition has no target step";
    QTest::newRow("unknown target step") << "transitions/2/to"
                                         << "[3, 12]" << p + ".transitions[2].to: unknown step 12";
    QTest::newRow("empty initial situation")
        << "steps/0/initial"
        << "false" << p + ".steps: empty initial situation: no step is marked initial";
    QTest::newRow("duplicate step id") << "steps/4/id"
                                       << "3" << p + ".steps[4].id: duplicate step id 3 (also step #3 in the list)";
    QTest::newRow("duplicate transition id")
        << "transitions/6/id"
        << "1" << p + ".transitions[6].id: duplicate transition id 1 (also transition #1 in the list)";
    QTest::newRow("unreachable") << "transitions/0/to"
                                 << "[1]"
                                 << p + ".steps[1]: unreachable step 'No Contact and No Chatter': no transition from "
                                        "the initial situation leads to it";
    QTest::newRow("id not an integer") << "steps/1/id"
                                       << "1.5" << p + ".steps[1].id = 1.5: must be an integer in [0, 1000000000]";
    QTest::newRow("negative id") << "transitions/0/id"
                                 << "-1" << p + ".transitions[0].id = -1: must be an integer in [0, 1000000000]";
    QTest::newRow("id missing") << "steps/2/id"
                                << "" << p + ".steps[2].id: missing";
    QTest::newRow("name missing") << "steps/2/name"
                                  << "" << p + ".steps[2].name: missing";
    QTest::newRow("initial not bool") << "steps/0/initial"
                                      << "1" << p + ".steps[0].initial = 1: must be true or false";
    QTest::newRow("action not a string")
        << "steps/1/actions"
        << "[\"A\", 3]" << p + ".steps[1].actions[1] = 3: must be a string (\"A\", or \"L*\" for an impulse)";
    QTest::newRow("from entry not an id")
        << "transitions/4/from"
        << "[\"4\"]" << p + ".transitions[4].from[0] = \"4\": must be an integer in [0, 1000000000]";
    QTest::newRow("receptivity not a string") << "transitions/4/receptivity"
                                              << "true" << p + ".transitions[4].receptivity = true: must be a string";
    QTest::newRow("priority") << "transitions/4/priority"
                              << "\"high\""
                              << p + ".transitions[4].priority = \"high\": must be an integer in [0, 1000000000]";
    QTest::newRow("steps not an array") << "steps"
                                        << "{}" << p + ".steps = (an object): must be an array";
    QTest::newRow("steps missing") << "steps"
                                   << "" << p + ".steps: missing";
    QTest::newRow("step not an object") << "steps/2"
                                        << "7" << p + ".steps[2] = 7: must be an object";
    QTest::newRow("bad action")
        << "steps/3/actions"
        << "[\"L **\"]"
        << p + ".steps[3].actions: bad action 'L **': a name, with a trailing '*' for an impulse action";
  }
  void errorsNameTheJsonPath() {
    QFETCH(QString, pointer);
    QFETCH(QString, json);
    QFETCH(QString, error);
    QJsonObject root = parse(kSmc1);
    const QJsonValue value = json.isEmpty() ? QJsonValue(QJsonValue::Undefined)
                                            : QJsonDocument::fromJson(("[" + json + "]").toUtf8()).array().at(0);
    const QStringList parts = pointer.split('/');
    if (parts.size() == 1) {
      if (json.isEmpty())
        root.remove(parts[0]);
      else
        root[parts[0]] = value;
    } else {
      QJsonArray list = root[parts[0]].toArray();
      const int i = parts[1].toInt();
      if (parts.size() == 2) {
        list[i] = value;
      } else {
        QJsonObject element = list[i].toObject();
        if (json.isEmpty())
          element.remove(parts[2]);
        else
          element[parts[2]] = value;
        list[i] = element;
      }
      root[parts[0]] = list;
    }
    QCOMPARE(grafcetErrorOf(root, std::set<std::string>{"a", "b"}), error);
  }

  void chartMustBeAnObject() {
    QCOMPARE(grafcetErrorOf(QJsonValue(3)), QString("supervisor.charts.smc1 = 3: must be an object"));
  }

  void listsAllErrors() {
    QJsonObject root = parse(kSmc1);
    QJsonArray t = root["transitions"].toArray();
    QJsonObject t0 = t[0].toObject();
    t0["receptivity"] = "a and";
    t[0] = t0;
    root["transitions"] = t;
    const GrafcetChart c = grafcetChartFromJson(root, "c").chart;
    const QStringList errors = grafcetChartErrors(c, "c", std::set<std::string>{"b"});
    QCOMPARE(errors, (QStringList{"c.transitions[0].receptivity: line 1, column 6: expected a signal, a number or '(', "
                                  "found the end of the expression",
                                  "c.transitions[1].receptivity: unknown signal 'a'",
                                  "c.transitions[4].receptivity: unknown signal 'a'",
                                  "c.transitions[6].receptivity: unknown signal 'a'"}));
    QVERIFY(grafcetChartErrors(c, "c").size() == 1);  // without the signal check
  }
};

MX_REGISTER_TEST(TestGrafcetJson)
#include "test_project_grafcet_io.moc"
