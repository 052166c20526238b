// Grafcet charts in JSON (issue 8): round trip, defaults, keys of the editor kept, and every error
// naming its JSON path (structure errors and validation issues, receptivity errors with line and
// column).
#include <QJsonArray>
#include <QJsonDocument>

#include "cli/cli_support.h"
#include "document/grafcet_json.h"
#include "document/project.h"
#include "supervisor/grafcet_interpreter.h"
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

QJsonObject parse(const char* text) { return QJsonDocument::fromJson(text).object(); }

QString errorOf(const QJsonValue& v, const std::optional<std::set<std::string>>& known = std::nullopt) {
  try {
    loadGrafcetChart(v, "supervisor.charts.smc1", known);
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
    const GrafcetChart c = loadGrafcetChart(parse(kSmc1), "chart", std::set<std::string>{"a", "b"});
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
    const GrafcetChart c = grafcetChartFromJson(original, "chart");
    const QJsonObject written = grafcetChartToJson(c);
    const GrafcetChart back = grafcetChartFromJson(written, "chart");
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
    // Writing again gives the same JSON; "initial" only where true.
    QCOMPARE(grafcetChartToJson(back), written);
    QVERIFY(!written["steps"].toArray()[1].toObject().contains("initial"));
  }

  void keepsUnknownKeysOfThePrevious() {
    QJsonObject original = parse(kSmc1);
    original["layout"] = "vertical";
    QJsonArray steps = original["steps"].toArray();
    QJsonObject s2 = steps[1].toObject();
    s2["x"] = 120;
    steps[1] = s2;
    original["steps"] = steps;
    GrafcetChart c = grafcetChartFromJson(original, "chart");
    c.steps[1].name = "Renamed";
    const QJsonObject written = grafcetChartToJson(c, original);
    QCOMPARE(written["layout"].toString(), QString("vertical"));
    QCOMPARE(written["steps"].toArray()[1].toObject()["x"].toInt(), 120);
    QCOMPARE(written["steps"].toArray()[1].toObject()["name"].toString(), QString("Renamed"));
  }

  void errorsNameTheJsonPath_data() {
    QTest::addColumn<QString>("pointer");  // what to change: "<list>/<index>/<key>" or "<key>"
    QTest::addColumn<QString>("json");     // the new value, as JSON (empty: remove the key)
    QTest::addColumn<QString>("error");
    const QString p = "supervisor.charts.smc1";
    QTest::newRow("receptivity syntax") << "transitions/3/receptivity" << "\"(a b\""
                                        << p + ".transitions[3].receptivity: line 1, column 4: expected ')'";
    QTest::newRow("unknown signal") << "transitions/6/receptivity" << "\"z'\""
                                    << p + ".transitions[6].receptivity: unknown signal 'z'";
    QTest::newRow("no source") << "transitions/2/from" << "[]" << p + ".transitions[2].from: the transition has no source step";
    QTest::newRow("no target") << "transitions/2/to" << "[]" << p + ".transitions[2].to: the transition has no target step";
    QTest::newRow("unknown target step") << "transitions/2/to" << "[3, 12]" << p + ".transitions[2].to: unknown step 12";
    QTest::newRow("empty initial situation") << "steps/0/initial" << "false"
                                             << p + ".steps: empty initial situation: no step is marked initial";
    QTest::newRow("duplicate step id") << "steps/4/id" << "3" << p + ".steps[4].id: duplicate step id 3 (also step #3 in the list)";
    QTest::newRow("duplicate transition id") << "transitions/6/id" << "1"
                                             << p + ".transitions[6].id: duplicate transition id 1 (also transition #1 in the list)";
    QTest::newRow("unreachable") << "transitions/0/to" << "[1]"
                                 << p + ".steps[1]: unreachable step 'No Contact and No Chatter': no transition from the initial situation leads to it";
    QTest::newRow("id not an integer") << "steps/1/id" << "1.5" << p + ".steps[1].id = 1.5: must be an integer in [0, 1000000000]";
    QTest::newRow("negative id") << "transitions/0/id" << "-1" << p + ".transitions[0].id = -1: must be an integer in [0, 1000000000]";
    QTest::newRow("id missing") << "steps/2/id" << "" << p + ".steps[2].id: missing";
    QTest::newRow("name missing") << "steps/2/name" << "" << p + ".steps[2].name: missing";
    QTest::newRow("initial not bool") << "steps/0/initial" << "1" << p + ".steps[0].initial = 1: must be true or false";
    QTest::newRow("action not a string") << "steps/1/actions" << "[\"A\", 3]"
                                         << p + ".steps[1].actions[1] = 3: must be a string (\"A\", or \"L*\" for an impulse)";
    QTest::newRow("from entry not an id") << "transitions/4/from" << "[\"4\"]"
                                          << p + ".transitions[4].from[0] = \"4\": must be an integer in [0, 1000000000]";
    QTest::newRow("receptivity not a string") << "transitions/4/receptivity" << "true"
                                              << p + ".transitions[4].receptivity = true: must be a string";
    QTest::newRow("priority") << "transitions/4/priority" << "\"high\""
                              << p + ".transitions[4].priority = \"high\": must be an integer in [0, 1000000000]";
    QTest::newRow("steps not an array") << "steps" << "{}" << p + ".steps = (an object): must be an array";
    QTest::newRow("steps missing") << "steps" << "" << p + ".steps: missing";
    QTest::newRow("step not an object") << "steps/2" << "7" << p + ".steps[2] = 7: must be an object";
    QTest::newRow("bad action") << "steps/3/actions" << "[\"L **\"]"
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
      if (json.isEmpty()) root.remove(parts[0]); else root[parts[0]] = value;
    } else {
      QJsonArray list = root[parts[0]].toArray();
      const int i = parts[1].toInt();
      if (parts.size() == 2) {
        list[i] = value;
      } else {
        QJsonObject element = list[i].toObject();
        if (json.isEmpty()) element.remove(parts[2]); else element[parts[2]] = value;
        list[i] = element;
      }
      root[parts[0]] = list;
    }
    QCOMPARE(errorOf(root, std::set<std::string>{"a", "b"}), error);
  }

  void chartMustBeAnObject() {
    QCOMPARE(errorOf(QJsonValue(3)), QString("supervisor.charts.smc1 = 3: must be an object"));
  }

  void listsAllErrors() {
    QJsonObject root = parse(kSmc1);
    QJsonArray t = root["transitions"].toArray();
    QJsonObject t0 = t[0].toObject();
    t0["receptivity"] = "a and";
    t[0] = t0;
    root["transitions"] = t;
    const GrafcetChart c = grafcetChartFromJson(root, "c");
    const QStringList errors = grafcetChartErrors(c, "c", std::set<std::string>{"b"});
    QCOMPARE(errors, (QStringList{
        "c.transitions[0].receptivity: line 1, column 6: expected a signal, a number or '(', found the end of the expression",
        "c.transitions[1].receptivity: unknown signal 'a'", "c.transitions[4].receptivity: unknown signal 'a'",
        "c.transitions[6].receptivity: unknown signal 'a'"}));
    QVERIFY(grafcetChartErrors(c, "c").size() == 1);  // without the signal check
  }
};

MX_REGISTER_TEST(TestGrafcetJson)
#include "test_grafcet_json.moc"
