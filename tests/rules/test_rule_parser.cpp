// The operator rule language (Module VII, Rule 18): lexer and parser. Every error of the language with
// its exact line, column and message; the issue's examples; and/or/not precedence; advice syntax.
#include "rules/rule_parser.h"
#include "test_registry.h"

using namespace mx;

namespace {

std::vector<std::string> toLines(const QStringList& list) {
  std::vector<std::string> lines;
  for (const QString& s : list) lines.push_back(s.toStdString());
  return lines;
}

Rule onlyRule(const RuleParseResult& r) {  // by value: callers pass a temporary
  if (!r.ok()) qFatal("unexpected parse error: %s", r.errors.front().toString().c_str());
  if (r.rules.size() != 1) qFatal("expected one rule, got %d", static_cast<int>(r.rules.size()));
  return r.rules.rules.front();
}

}  // namespace

class TestRuleParser : public QObject {
  Q_OBJECT

 private slots:
  void issueExamplesParse() {
    const RuleParseResult r = parseRules(
        {"if tool.diameter_mm < 10 then speed_rpm <= 8000", "if material.name == \"Ti6Al4V\" then weight.c3 >= 0.2"});
    QVERIFY(r.ok());
    QCOMPARE(r.rules.size(), std::size_t(2));
    const Rule& a = r.rules.rules[0];
    QCOMPARE(a.line, 1);
    QCOMPARE(a.kind, RuleKind::Constraint);
    QCOMPARE(toString(a.condition), std::string("tool.diameter_mm < 10"));
    QVERIFY(a.bound.has_value());
    QCOMPARE(a.bound->variable, std::string("speed_rpm"));
    QCOMPARE(a.bound->op, BoundOp::LessEq);
    QCOMPARE(a.bound->value, 8000.0);
    QCOMPARE(a.bound->column, 31);
    const Rule& b = r.rules.rules[1];
    QCOMPARE(b.line, 2);
    QCOMPARE(toString(b.condition), std::string("material.name == \"Ti6Al4V\""));
    QCOMPARE(b.bound->toString(), std::string("weight.c3 >= 0.2"));
    QCOMPARE(b.text, std::string("if material.name == \"Ti6Al4V\" then weight.c3 >= 0.2"));
  }

  void consequenceForms_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("kind");  // 0 constraint, 1 advice
    QTest::addColumn<QString>("bound");
    QTest::addColumn<QString>("message");
    QTest::addColumn<QString>("condition");
    QTest::newRow("unconditional constraint") << "depth_mm <= 3" << 0 << "depth_mm <= 3"
                                              << ""
                                              << "";
    QTest::newRow("equality bound") << "weight.c1 == 0.25" << 0 << "weight.c1 == 0.25"
                                    << ""
                                    << "";
    QTest::newRow("because keeps a constraint")
        << "if machine.max_spindle_rpm <= 12000 then speed_rpm <= 11000 because \"keep a margin\"" << 0
        << "speed_rpm <= 11000"
        << "keep a margin"
        << "machine.max_spindle_rpm <= 12000";
    QTest::newRow("advice clause") << "if tool.teeth >= 4 and operation.milling == \"down\" then feed_mm_per_tooth <= "
                                      "0.1 advice \"small feed for many teeth\""
                                   << 1 << "feed_mm_per_tooth <= 0.1"
                                   << "small feed for many teeth"
                                   << "tool.teeth >= 4 and operation.milling == \"down\"";
    QTest::newRow("advise bound") << "if tool.Kr > 0.5 then advise depth_mm <= 1" << 1 << "depth_mm <= 1"
                                  << ""
                                  << "tool.Kr > 0.5";
    QTest::newRow("advise bound because")
        << "advise speed_rpm >= 2000 because \"built-up edge\"" << 1 << "speed_rpm >= 2000"
        << "built-up edge"
        << "";
    QTest::newRow("advise message only") << "if material.name == \"Inconel\" then advise \"use coolant\"" << 1 << ""
                                         << "use coolant"
                                         << "material.name == \"Inconel\"";
    QTest::newRow("negative and exponent numbers")
        << "if tool.helix_deg > -1.5e1 then power_W <= 2.5e3 # note" << 0 << "power_W <= 2500"
        << ""
        << "tool.helix_deg > -15";
    QTest::newRow("escaped quote") << "if machine.name == \"the \\\"big\\\" one\" then speed_rpm <= 100" << 0
                                   << "speed_rpm <= 100"
                                   << ""
                                   << "machine.name == \"the \\\"big\\\" one\"";
  }
  void consequenceForms() {
    QFETCH(QString, text);
    QFETCH(int, kind);
    QFETCH(QString, bound);
    QFETCH(QString, message);
    QFETCH(QString, condition);
    const Rule rule = onlyRule(parseRules({text.toStdString()}));
    QCOMPARE(rule.kind, kind == 0 ? RuleKind::Constraint : RuleKind::Advice);
    QCOMPARE(QString::fromStdString(rule.bound ? rule.bound->toString() : ""), bound);
    QCOMPARE(QString::fromStdString(rule.message), message);
    QCOMPARE(QString::fromStdString(toString(rule.condition)), condition);
    QCOMPARE(rule.unconditional(), condition.isEmpty());
  }

  // The tree shape shows in the canonical text: parentheses appear only where the tree needs them.
  void precedence_data() {
    QTest::addColumn<QString>("condition");
    QTest::addColumn<QString>("canonical");
    QTest::newRow("and binds tighter than or") << "tool.teeth == 1 or tool.teeth == 2 and tool.Kr > 0"
                                               << "tool.teeth == 1 or tool.teeth == 2 and tool.Kr > 0";
    QTest::newRow("parentheses group or") << "(tool.teeth == 1 or tool.teeth == 2) and tool.Kr > 0"
                                          << "(tool.teeth == 1 or tool.teeth == 2) and tool.Kr > 0";
    QTest::newRow("redundant parentheses dropped") << "tool.teeth == 1 or (tool.teeth == 2 and tool.Kr > 0)"
                                                   << "tool.teeth == 1 or tool.teeth == 2 and tool.Kr > 0";
    QTest::newRow("not binds tighter than and") << "not tool.teeth == 1 and tool.Kr > 0"
                                                << "not tool.teeth == 1 and tool.Kr > 0";
    QTest::newRow("not of a group") << "not (tool.teeth == 1 and tool.Kr > 0)"
                                    << "not (tool.teeth == 1 and tool.Kr > 0)";
    QTest::newRow("double not") << "not not tool.teeth == 1"
                                << "not not tool.teeth == 1";
    QTest::newRow("nested groups") << "((tool.Kr > 0))"
                                   << "tool.Kr > 0";
    QTest::newRow("or is left-associative") << "tool.Kr > 0 or tool.Kr < 1 or tool.teeth != 3"
                                            << "tool.Kr > 0 or tool.Kr < 1 or tool.teeth != 3";
  }
  void precedence() {
    QFETCH(QString, condition);
    QFETCH(QString, canonical);
    const Rule rule = onlyRule(parseRules({"if " + condition.toStdString() + " then depth_mm <= 1"}));
    QCOMPARE(QString::fromStdString(toString(rule.condition)), canonical);
  }

  void treeShape() {
    const Rule rule =
        onlyRule(parseRules({"if tool.teeth == 1 or tool.teeth == 2 and not tool.Kr > 0 then depth_mm <= 1"}));
    QCOMPARE(rule.condition->kind, ConditionNode::Kind::Or);
    QCOMPARE(rule.condition->left->kind, ConditionNode::Kind::Compare);
    QCOMPARE(rule.condition->right->kind, ConditionNode::Kind::And);
    QCOMPARE(rule.condition->right->right->kind, ConditionNode::Kind::Not);
    QCOMPARE(rule.condition->right->right->left->comparison.path, std::string("tool.Kr"));
    QCOMPARE(rule.condition->right->right->left->comparison.column, 47);
  }

  // Every error of the language: the exact line, column and message. The error line is preceded by
  // `lineOffset` blank/comment lines, so line numbers count them.
  void errors_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("message");
    // Lexical errors.
    QTest::newRow("unterminated string") << "if material.name == \"Ti6Al4V then weight.c3 >= 0.2" << 21
                                         << "unterminated string: missing the closing '\"'";
    QTest::newRow("bad number in condition")
        << "if tool.diameter_mm < 1.2.3 then speed_rpm <= 8000" << 23 << "bad number '1.2.3'";
    QTest::newRow("bad number in action") << "speed_rpm <= 8000rpm" << 14 << "bad number '8000rpm'";
    QTest::newRow("bad exponent") << "speed_rpm <= 1e" << 14 << "bad number '1e'";
    QTest::newRow("unexpected character")
        << "if tool.teeth >= 4 & tool.teeth < 8 then depth_mm <= 2" << 20 << "unexpected character '&'";
    QTest::newRow("single equals") << "if tool.teeth = 4 then depth_mm <= 2" << 15
                                   << "unexpected '=': write '==' to compare";
    QTest::newRow("path ending in a dot") << "if tool. < 3 then depth_mm <= 2" << 9 << "expected a name after 'tool.'";
    QTest::newRow("columns count code points")
        << "if material.name == \"\xc3\x98\" and tool.teeth < 2.5.1 then depth_mm <= 1" << 42 << "bad number '2.5.1'";
    // Syntax errors.
    QTest::newRow("missing comparison operator")
        << "if tool.diameter_mm then speed_rpm <= 8000" << 21
        << "expected a comparison operator (<, <=, >, >=, ==, !=) after 'tool.diameter_mm', got 'then'";
    QTest::newRow("missing value") << "if tool.diameter_mm < then speed_rpm <= 8000" << 23
                                   << "expected a number after 'tool.diameter_mm <', got 'then'";
    QTest::newRow("missing string value") << "if material.name != then speed_rpm <= 8000" << 21
                                          << "expected a \"string\" after 'material.name !=', got 'then'";
    QTest::newRow("missing then") << "if tool.teeth >= 4 speed_rpm <= 8000" << 20
                                  << "expected 'then', 'and' or 'or' after the condition, got 'speed_rpm'";
    QTest::newRow("empty condition") << "if then speed_rpm <= 8000" << 4
                                     << "expected a condition after 'if', got 'then'";
    QTest::newRow("condition missing at end") << "if" << 3 << "expected a condition after 'if', got end of rule";
    QTest::newRow("empty parentheses") << "if () then speed_rpm <= 1" << 5 << "expected a condition after '(', got ')'";
    QTest::newRow("dangling and")
        << "if tool.teeth >= 4 and then depth_mm <= 2" << 24
        << "expected a comparison such as 'tool.teeth >= 4', 'not' or '(' after 'and', got 'then'";
    QTest::newRow("dangling not")
        << "if not then depth_mm <= 2" << 8
        << "expected a comparison such as 'tool.teeth >= 4', 'not' or '(' after 'not', got 'then'";
    QTest::newRow("unclosed parenthesis") << "if (tool.teeth >= 4 then depth_mm <= 2" << 21
                                          << "expected ')' to close the '(' at column 4, or 'and'/'or', got 'then'";
    QTest::newRow("unmatched parenthesis")
        << "if tool.teeth >= 4) then depth_mm <= 2" << 19
        << "expected 'then' (this ')' has no matching '(') after the condition, got ')'";
    QTest::newRow("unexpected token after then") << "if tool.teeth >= 4 then ) speed_rpm <= 1" << 25
                                                 << "expected a decision variable or 'advise' after 'then', got ')'";
    QTest::newRow("missing action") << "if tool.teeth >= 4 then" << 24
                                    << "expected a decision variable or 'advise' after 'then', got end of rule";
    QTest::newRow("rule starts with a keyword")
        << "then speed_rpm <= 1" << 1 << "expected 'if', 'advise' or a decision variable, got 'then'";
    QTest::newRow("rule starts with a number")
        << "8000 >= speed_rpm" << 1 << "expected 'if', 'advise' or a decision variable, got '8000'";
    QTest::newRow("strict bound") << "speed_rpm < 8000" << 11 << "a bound uses <=, >= or ==, got '<'";
    QTest::newRow("bound without operator")
        << "speed_rpm 8000" << 11 << "expected <=, >= or == after 'speed_rpm', got '8000'";
    QTest::newRow("bound with a string") << "if tool.teeth >= 4 then speed_rpm <= \"fast\"" << 38
                                         << "expected a number after 'speed_rpm <=', got \"fast\"";
    QTest::newRow("advise without anything")
        << "advise" << 7 << "expected a decision variable or a \"text\" after 'advise', got end of rule";
    QTest::newRow("advice clause without text")
        << "speed_rpm <= 8000 advice" << 25 << "expected a \"text\" after 'advice', got end of rule";
    QTest::newRow("trailing garbage")
        << "speed_rpm <= 8000 extra" << 19
        << "expected end of rule, 'advice \"...\"' or 'because \"...\"' after 'speed_rpm <= 8000', got 'extra'";
    QTest::newRow("trailing garbage after advice")
        << "speed_rpm <= 8000 advice \"slow\" now" << 33 << "expected end of rule after the advice text, got 'now'";
    QTest::newRow("trailing garbage after message advice")
        << "advise \"slow\" 3" << 15 << "expected end of rule after the advice text, got '3'";
    QTest::newRow("trailing second comparison") << "if tool.teeth >= 4 < 5 then depth_mm <= 2" << 20
                                                << "expected 'then', 'and' or 'or' after the condition, got '<'";
    // Semantic errors.
    QTest::newRow("unknown path")
        << "if tool.diamter_mm < 10 then speed_rpm <= 8000" << 4
        << "unknown path 'tool.diamter_mm' (known: tool.Kr, tool.Kt_N_mm2, tool.diameter_mm, tool.helix_deg, tool.id, "
           "tool.modes, tool.teeth)";
    QTest::newRow("unknown root") << "if spindle.rpm > 3 then depth_mm <= 2" << 4
                                  << "unknown path 'spindle.rpm' (known: machine.*, material.*, operation.*, tool.*)";
    QTest::newRow("decision variable in condition") << "if speed_rpm > 3 then depth_mm <= 2" << 4
                                                    << "'speed_rpm' is a decision variable; conditions test context "
                                                       "paths (machine.*, material.*, operation.*, tool.*)";
    QTest::newRow("unknown variable")
        << "if tool.teeth >= 4 then speed <= 8000" << 25
        << "unknown decision variable 'speed' (one of: depth_mm, feed_mm_per_tooth, feed_velocity_mm_s, mrr_cm3_s, "
           "power_W, speed_rpm, weight.c1, weight.c2, weight.c3, weight.mrr, weight.ros, weight.surf, weight.tol)";
    QTest::newRow("path as variable")
        << "tool.teeth <= 3" << 1
        << "'tool.teeth' is a context path, not a decision variable; bound one of: depth_mm, feed_mm_per_tooth, "
           "feed_velocity_mm_s, mrr_cm3_s, power_W, speed_rpm, weight.c1, weight.c2, weight.c3, weight.mrr, "
           "weight.ros, "
           "weight.surf, weight.tol";
    QTest::newRow("string path against number")
        << "if material.name == 5 then weight.c3 >= 0.2" << 21
        << "type mismatch: 'material.name' is a string, compared with the number 5";
    QTest::newRow("number path against string")
        << "if tool.diameter_mm < \"ten\" then speed_rpm <= 8000" << 23
        << "type mismatch: 'tool.diameter_mm' is a number, compared with the string \"ten\"";
    QTest::newRow("ordering a string path") << "if material.name < \"T\" then speed_rpm <= 8000" << 18
                                            << "'<' does not apply to the string path 'material.name': use == or !=";
  }
  void errors() {
    QFETCH(QString, text);
    QFETCH(int, column);
    QFETCH(QString, message);
    // The bad rule is line 4, after a comment, a valid rule and a blank line.
    const RuleParseResult r = parseRules(toLines({"# operator rules", "depth_mm <= 5", "   ", text}));
    QCOMPARE(r.errors.size(), std::size_t(1));
    const RuleError& e = r.errors.front();
    QCOMPARE(QString::fromStdString(e.message), message);
    QCOMPARE(e.line, 4);
    QCOMPARE(e.column, column);
    QCOMPARE(QString::fromStdString(e.toString()), QString("line 4, column %1: %2").arg(column).arg(message));
    QCOMPARE(r.rules.size(), std::size_t(1));  // the valid line survives
    QCOMPARE(r.rules.rules.front().line, 2);
  }

  void everyBadLineIsReported() {
    const RuleParseResult r = parseRuleText(
        "if tool.diameter_mm < 10 then speed_rpm <= 8000\n"
        "if tool.teeth >= 4 speed_rpm <= 8000\n"
        "\n"
        "speed_rpm <= 8000 extra\n"
        "if material.name == \"Ti6Al4V\" then weight.c3 >= 0.2");
    QCOMPARE(r.errors.size(), std::size_t(2));
    QCOMPARE(r.errors[0].line, 2);
    QCOMPARE(r.errors[0].column, 20);
    QCOMPARE(r.errors[1].line, 4);
    QCOMPARE(r.errors[1].column, 19);
    QCOMPARE(r.rules.size(), std::size_t(2));
    QCOMPARE(r.rules.rules[1].line, 5);
  }

  void throwingVariantListsAllErrors() {
    try {
      parseRulesOrThrow({"speed_rpm < 1", "if then depth_mm <= 1"});
      QFAIL("expected RuleSyntaxError");
    } catch (const RuleSyntaxError& e) {
      QCOMPARE(e.errors().size(), std::size_t(2));
      QCOMPARE(std::string(e.what()), std::string("line 1, column 11: a bound uses <=, >= or ==, got '<'\n"
                                                  "line 2, column 4: expected a condition after 'if', got 'then'"));
    }
    QCOMPARE(parseRulesOrThrow({"depth_mm <= 1"}).size(), std::size_t(1));
  }

  void blankAndCommentLinesAreNotRules() {
    const RuleParseResult r = parseRules({"", "  # only a comment", "\t"});
    QVERIFY(r.ok());
    QVERIFY(r.rules.empty());
  }

  // Nesting: kMaxRuleNesting levels of '(' or 'not' parse; one more is refused at the token that opens
  // it. 20 000 of them, far past any stack, give the same error instead of an overflow.
  void nestingLimit_data() {
    QTest::addColumn<QString>("open");
    QTest::addColumn<QString>("close");
    QTest::addColumn<int>("levels");
    QTest::addColumn<bool>("ok");
    const int max = kMaxRuleNesting;
    QTest::newRow("parentheses at the limit") << "("
                                              << ")" << max << true;
    QTest::newRow("parentheses past the limit") << "("
                                                << ")" << max + 1 << false;
    QTest::newRow("20000 parentheses") << "("
                                       << ")" << 20000 << false;
    QTest::newRow("nots at the limit") << "not "
                                       << "" << max << true;
    QTest::newRow("nots past the limit") << "not "
                                         << "" << max + 1 << false;
    QTest::newRow("mixed past the limit") << "not ("
                                          << ")" << max / 2 + 1 << false;
  }
  void nestingLimit() {
    QFETCH(QString, open);
    QFETCH(QString, close);
    QFETCH(int, levels);
    QFETCH(bool, ok);
    const QString condition = open.repeated(levels) + "tool.teeth >= 4" + close.repeated(levels);
    const std::string line = ("if " + condition + " then depth_mm <= 1").toStdString();
    RuleParser parser(RuleSchema::standard());
    Rule rule;
    bool isRule = false;
    RuleError error;
    QCOMPARE(parser.parseLine(line, 1, rule, isRule, error), ok);
    if (ok) return;
    if (line.size() > kMaxRuleLineLength) {  // far past any stack: the length limit refuses it first
      QVERIFY(error.message.starts_with("rule is " + std::to_string(line.size()) + " characters long"));
      return;
    }
    QCOMPARE(
        QString::fromStdString(error.message),
        QString("nested too deeply: more than %1 '(' and 'not' open at once; split the rule").arg(kMaxRuleNesting));
    // The first token past the limit: the (kMaxRuleNesting + 1)-th opening token.
    const int perLevel = static_cast<int>(open.size());
    const int tokensPerLevel = open.count('(') + open.count("not");
    const int overflowLevel = kMaxRuleNesting / tokensPerLevel;
    const int expected = 4 + overflowLevel * perLevel;
    QCOMPARE(error.column, expected);
  }

  void lineLengthLimit() {
    const std::string head = "depth_mm <= 1 because \"";
    const std::string filler(kMaxRuleLineLength - head.size() - 1, 'x');
    const std::string atLimit = head + filler + "\"";
    QCOMPARE(atLimit.size(), kMaxRuleLineLength);
    QVERIFY(parseRules({atLimit}).ok());
    const RuleParseResult over = parseRules({atLimit + " "});
    QCOMPARE(over.errors.size(), std::size_t(1));
    QCOMPARE(over.errors.front().column, static_cast<int>(kMaxRuleLineLength) + 1);
    QCOMPARE(over.errors.front().message,
             "rule is " + std::to_string(kMaxRuleLineLength + 1) + " characters long; at most 1000 are allowed");
  }

  void lineCountLimit() {
    std::vector<std::string> lines(kMaxRuleLines, "depth_mm <= 1");
    QCOMPARE(parseRules(lines).rules.size(), kMaxRuleLines);
    lines.emplace_back("# one line too many");
    const RuleParseResult over = parseRules(lines);
    QCOMPARE(over.errors.size(), std::size_t(1));
    QCOMPARE(over.errors.front().line, static_cast<int>(kMaxRuleLines) + 1);
    QCOMPARE(over.errors.front().message, std::string("1001 rule lines; at most 1000 are allowed"));
    QVERIFY(over.rules.empty());
  }

  // Columns count UTF-8 characters, not bytes, also after the per-line column table.
  void columnsCountCharacters() {
    const RuleParseResult r = parseRules({"depth_mm <= 1 because \"\u00e9\u00e9\" x"});
    QCOMPARE(r.errors.size(), std::size_t(1));
    QCOMPARE(r.errors.front().column, 28);
  }

  void schemaCanBeExtended() {
    RuleSchema schema = RuleSchema::standard();
    schema.addPath("job.batch_size", RuleValueType::Number);
    schema.addVariable("radial_depth_mm");
    const RuleParseResult r = parseRules({"if job.batch_size > 100 then radial_depth_mm <= 2"}, schema);
    QVERIFY(r.ok());
    QVERIFY(!parseRules({"if job.batch_size > 100 then depth_mm <= 2"}).ok());
  }
};

MX_REGISTER_TEST(TestRuleParser)
#include "test_rule_parser.moc"
