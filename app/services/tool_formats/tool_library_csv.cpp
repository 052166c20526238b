#include "services/tool_formats/tool_library_csv.h"

#include <QHash>
#include <QLocale>
#include <QRegularExpression>
#include <QSet>
#include <algorithm>
#include <optional>
#include <vector>

#include "core/invalid_input.h"
#include "document/input_files.h"
#include "document/json_format.h"
#include "document/output_file.h"
#include "document/project_rules.h"
#include "document/project_validation.h"
#include "document/tool_geometry.h"
#include "document/tooth_list_text.h"

namespace mx::app {

namespace {

enum Col {
  kId,
  kTeeth,
  kDiameter,
  kHelix,
  kPitch,
  kRunout,
  kKt,
  kKr,
  kKte,
  kKre,
  kKa,
  kKae,
  kRadial,
  kMaxForce,
  kAxis,
  kFreq,
  kDamping,
  kStiffness,
  kColumnCount
};

// Columns a header may leave out (a library written before they existed); their cells read as blank.
bool optionalColumn(int col) {
  return col == kMaxForce || col == kPitch || col == kRunout || col == kKte || col == kKre || col == kKa || col == kKae;
}

// The per-tool overrides of the material's edge and axial coefficients: their columns and fields.
struct CoefficientColumn {
  Col col;
  std::optional<double> ToolSpec::*field;
  const NumberRule* rule;
};
const CoefficientColumn kCoefficientColumns[] = {{kKte, &ToolSpec::Kte_N_mm, &rules::kEdgeForceNmm},
                                                 {kKre, &ToolSpec::Kre_N_mm, &rules::kEdgeForceNmm},
                                                 {kKa, &ToolSpec::Ka_N_mm2, &rules::kAxialPressureNmm2},
                                                 {kKae, &ToolSpec::Kae_N_mm, &rules::kEdgeForceNmm}};

// Splits one CSV line (RFC 4180 quoting, no line breaks inside a field). Cells are trimmed unless quoted.
bool splitCsvLine(const QString& line, QStringList& cells) {
  cells.clear();
  QString cell;
  bool quoted = false, wasQuoted = false;
  for (qsizetype i = 0; i < line.size(); ++i) {
    const QChar c = line.at(i);
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line.at(i + 1) == '"') {
        cell += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cell += c;
      }
    } else if (c == '"' && cell.trimmed().isEmpty()) {
      quoted = wasQuoted = true;
      cell.clear();
    } else if (c == ',') {
      cells << (wasQuoted ? cell : cell.trimmed());
      cell.clear();
      wasQuoted = false;
    } else {
      cell += c;
    }
  }
  cells << (wasQuoted ? cell : cell.trimmed());
  return !quoted;
}

// Quoted when a bare cell would read back differently: a separator, a quote, outer spaces, or a '#'
// first, which would make the row a comment.
QString quoteCsv(const QString& text) {
  if (!text.contains(',') && !text.contains('"') && text.trimmed() == text && !text.startsWith('#')) return text;
  return '"' + QString(text).replace("\"", "\"\"") + '"';
}

// Parser state: the header's column positions and the tool being read.
class CsvReader {
 public:
  QString error;

  bool readHeader(int line, const QStringList& cells) {
    pos_.fill(-1, kColumnCount);
    for (qsizetype c = 0; c < cells.size(); ++c) {
      const qsizetype known = ToolLibraryCsv::columns().indexOf(cells[c]);
      if (known < 0)
        return fail(QString("line %1, column %2: unknown column '%3' (expected the header %4)")
                        .arg(line)
                        .arg(c + 1)
                        .arg(cells[c], ToolLibraryCsv::columns().join(',')));
      if (pos_[known] >= 0)
        return fail(QString("line %1, column %2: column '%3' given twice").arg(line).arg(c + 1).arg(cells[c]));
      pos_[known] = static_cast<int>(c);
    }
    for (int k = 0; k < kColumnCount; ++k) {
      if (pos_[k] < 0 && !optionalColumn(k))
        return fail(QString("line %1: missing column '%2' (the header must be %3)")
                        .arg(line)
                        .arg(ToolLibraryCsv::columns()[k], ToolLibraryCsv::columns().join(',')));
    }
    width_ = static_cast<int>(cells.size());
    return true;
  }

  bool readRow(int line, const QStringList& cells, ToolLibraryFile& out) {
    line_ = line;
    cells_ = cells;
    if (cells.size() != width_) {
      const auto at = std::min<qsizetype>(cells.size(), width_) + 1;
      return fail(QString("line %1, column %2: the row has %3 columns, expected %4")
                      .arg(line)
                      .arg(at)
                      .arg(cells.size())
                      .arg(width_));
    }
    const QString id = cell(kId);
    if (id.trimmed().isEmpty()) return bad(kId, "must be a non-empty tool id");  // a quoted " " too, as in a project
    const bool continuation = !out.tools.empty() && out.tools.back().id == id;
    if (!continuation) {
      if (firstLine_.contains(id))
        return bad(kId, QString("duplicate tool id (first on line %1); the rows of one tool must be consecutive")
                            .arg(firstLine_.value(id)));
      ToolSpec tool;
      tool.id = id;
      double teeth = 0.0;
      if (out.tools.size() >= static_cast<std::size_t>(rules::kMaxTools))
        return bad(
            kId,
            QString("is tool %1: a library holds at most %2 tools").arg(out.tools.size() + 1).arg(rules::kMaxTools));
      if (!required(kTeeth, rules::kTeeth, teeth) || !required(kDiameter, rules::kDiameterMm, tool.diameter_mm) ||
          !required(kHelix, rules::kHelixDeg, tool.helix_deg) ||
          !optional(kKt, rules::kCuttingPressureNmm2, tool.Kt_N_mm2) || !optional(kKr, rules::kForceRatio, tool.Kr) ||
          !coefficients(tool) || !optional(kRadial, rules::radialDepth(tool.diameter_mm), tool.radial_depth_mm) ||
          !optional(kMaxForce, rules::kToolForceN, tool.max_force_N))
        return false;
      tool.teeth = static_cast<int>(teeth);
      if (!toothList(kPitch, tool.pitch_deg) || !toothList(kRunout, tool.runout_um) || !geometry(tool)) return false;
      firstLine_.insert(id, line);
      out.tools.push_back(tool);
      out.lines.push_back(line);
    } else if (!sameAsFirst(out.tools.back())) {
      return false;
    }
    return readMode(out.tools.back(), continuation);
  }

 private:
  QString cell(int col) const { return pos_[col] < 0 ? QString() : cells_.at(pos_[col]); }

  bool fail(const QString& message) {
    error = message;
    return false;
  }
  bool bad(int col, const QString& what) {
    return fail(QString("line %1, column %2 (%3): '%4' %5")
                    .arg(line_)
                    .arg(pos_[col] + 1)
                    .arg(ToolLibraryCsv::columns()[col], cell(col), what));
  }
  bool number(int col, const NumberRule& rule, double& value) {
    bool ok = false;
    value = QLocale::c().toDouble(cell(col), &ok);
    if (!ok) return bad(col, "is not a number (" + rule.requirement() + ")");
    if (!rule.accepts(value)) return bad(col, rule.mustBe(value));
    return true;
  }
  bool required(int col, const NumberRule& rule, double& value) {
    if (cell(col).isEmpty()) return bad(col, "is empty (required " + rule.requirement() + ")");
    return number(col, rule, value);
  }
  bool optional(int col, const NumberRule& rule, std::optional<double>& value) {
    if (cell(col).isEmpty()) return true;
    double v = 0.0;
    if (!number(col, rule, v)) return false;
    value = v;
    return true;
  }
  bool coefficients(ToolSpec& tool) {
    for (const CoefficientColumn& c : kCoefficientColumns)
      if (!optional(c.col, *c.rule, tool.*c.field)) return false;
    return true;
  }
  // A ';'-separated list of numbers; a blank cell is no list (uniform pitch, no runout).
  bool toothList(int col, std::optional<std::vector<double>>& values) {
    if (cell(col).isEmpty()) return true;
    const ToothListParse parsed = parseToothList(cell(col));
    if (!parsed.ok())
      return bad(col, QString("value %1 ('%2') is not a number (numbers separated by ';', one per tooth)")
                          .arg(parsed.bad_item + 1)
                          .arg(parsed.bad_text));
    values = parsed.values;
    return true;
  }
  // The per-tooth lists against the tool's teeth and diameter; values are counted from 1.
  bool geometry(const ToolSpec& t) {
    const auto check = [&](int col, const ToothListIssue& issue, const std::vector<double>& values) {
      if (issue.ok()) return true;
      if (issue.index < 0) return bad(col, issue.rule);
      return bad(col, QString("value %1 (%2) %3")
                          .arg(issue.index + 1)
                          .arg(formatNumber(values[std::size_t(issue.index)]), issue.rule));
    };
    return (!t.pitch_deg || check(kPitch, pitchIssue(*t.pitch_deg, t.teeth), *t.pitch_deg)) &&
           (!t.runout_um || check(kRunout, runoutIssue(*t.runout_um, t.teeth, t.diameter_mm), *t.runout_um));
  }
  // A continuation row leaves the tool fields blank or repeats them exactly.
  bool sameAsFirst(const ToolSpec& t) {
    for (const auto& [col, first] : {std::pair{kPitch, t.pitch_deg}, {kRunout, t.runout_um}}) {
      if (cell(col).isEmpty()) continue;
      const ToothListParse parsed = parseToothList(cell(col));
      if (!parsed.ok() || !first || parsed.values != *first)
        return bad(col, QString("differs from the tool's first row (line %1, '%2'); leave it blank or repeat it")
                            .arg(firstLine_.value(t.id))
                            .arg(first ? toothListText(*first) : QString()));
    }
    const std::pair<int, std::optional<double>> fields[] = {{kTeeth, double(t.teeth)},
                                                            {kDiameter, t.diameter_mm},
                                                            {kHelix, t.helix_deg},
                                                            {kKt, t.Kt_N_mm2},
                                                            {kKr, t.Kr},
                                                            {kKte, t.Kte_N_mm},
                                                            {kKre, t.Kre_N_mm},
                                                            {kKa, t.Ka_N_mm2},
                                                            {kKae, t.Kae_N_mm},
                                                            {kRadial, t.radial_depth_mm},
                                                            {kMaxForce, t.max_force_N}};
    for (const auto& [col, first] : fields) {
      if (cell(col).isEmpty()) continue;
      bool ok = false;
      const double v = QLocale::c().toDouble(cell(col), &ok);
      if (!ok || !first || v != *first)
        return bad(col, QString("differs from the tool's first row (line %1, '%2'); leave it blank or repeat it")
                            .arg(firstLine_.value(t.id))
                            .arg(first ? formatNumber(*first) : QString()));
    }
    return true;
  }
  bool readMode(ToolSpec& tool, bool continuation) {
    const QString axis = cell(kAxis).toLower();
    if (axis.isEmpty()) {
      if (continuation) return bad(kAxis, "is empty: a further row of a tool must give a mode (axis x or y)");
      for (int col : {kFreq, kDamping, kStiffness}) {
        if (!cell(col).isEmpty()) return bad(col, "is given but the axis is empty (x or y)");
      }
      return true;
    }
    if (axis != "x" && axis != "y") return bad(kAxis, "must be x or y");
    ModeSpec m;
    std::vector<ModeSpec>& modes = axis == "x" ? tool.modes_x : tool.modes_y;
    if (modes.size() >= static_cast<std::size_t>(rules::kMaxModesPerAxis))
      return bad(kAxis, QString("is mode %1 of the axis: a tool has at most %2 modes per axis")
                            .arg(modes.size() + 1)
                            .arg(rules::kMaxModesPerAxis));
    if (!required(kFreq, rules::kModeFrequencyHz, m.freq_Hz) ||
        !required(kDamping, rules::kDampingPct, m.damping_pct) ||
        !required(kStiffness, rules::kStiffnessNPerUm, m.stiffness_N_per_um))
      return false;
    modes.push_back(m);
    return true;
  }

  QList<int> pos_;
  int width_ = 0;
  int line_ = 0;
  QStringList cells_;
  QHash<QString, int> firstLine_;
};

}  // namespace

const QStringList& ToolLibraryCsv::columns() {
  static const QStringList kColumns{
      "tool_id",         "teeth",       "diameter_mm", "helix_deg", "pitch_deg",   "runout_um",
      "Kt_N_mm2",        "Kr",          "Kte_N_mm",    "Kre_N_mm",  "Ka_N_mm2",    "Kae_N_mm",
      "radial_depth_mm", "max_force_N", "axis",        "freq_Hz",   "damping_pct", "stiffness_N_per_um"};
  return kColumns;
}

// The pitch and runout columns are written when some tool has that list, each edge or axial coefficient
// column when some tool overrides that coefficient: a library without them is written as before.
QByteArray ToolLibraryCsv::toCsv(const std::vector<ToolSpec>& tools) {
  const auto opt = [](const std::optional<double>& v) { return v ? formatNumber(*v) : QString(); };
  const auto list = [](const std::optional<std::vector<double>>& v) { return v ? toothListText(*v) : QString(); };
  const auto anyTool = [&](const auto& has) { return std::any_of(tools.begin(), tools.end(), has); };
  const bool pitch = anyTool([](const ToolSpec& t) { return t.pitch_deg.has_value(); });
  const bool runout = anyTool([](const ToolSpec& t) { return t.runout_um.has_value(); });
  QList<int> omitted;
  if (!pitch) omitted << kPitch;
  if (!runout) omitted << kRunout;
  std::vector<const CoefficientColumn*> coefficients;
  for (const CoefficientColumn& c : kCoefficientColumns) {
    if (anyTool([&](const ToolSpec& t) { return (t.*c.field).has_value(); }))
      coefficients.push_back(&c);
    else
      omitted << c.col;
  }
  QStringList header;
  for (int col = 0; col < kColumnCount; ++col)
    if (!omitted.contains(col)) header << columns()[col];
  QStringList lines{header.join(',')};
  for (const ToolSpec& t : tools) {
    QStringList fields{quoteCsv(t.id), QString::number(t.teeth), formatNumber(t.diameter_mm),
                       formatNumber(t.helix_deg)};
    if (pitch) fields << list(t.pitch_deg);
    if (runout) fields << list(t.runout_um);
    fields << opt(t.Kt_N_mm2) << opt(t.Kr);
    for (const CoefficientColumn* c : coefficients) fields << opt(t.*(c->field));
    fields << opt(t.radial_depth_mm) << opt(t.max_force_N);
    const QString head = fields.join(',');
    const auto mode = [&](const char* axis, const ModeSpec& m) {
      lines << QStringList{head, axis, formatNumber(m.freq_Hz), formatNumber(m.damping_pct),
                           formatNumber(m.stiffness_N_per_um)}
                   .join(',');
    };
    for (const ModeSpec& m : t.modes_x) mode("x", m);
    for (const ModeSpec& m : t.modes_y) mode("y", m);
    if (t.modes_x.empty() && t.modes_y.empty()) lines << head + ",,,,";
  }
  return (lines.join('\n') + '\n').toUtf8();
}

ToolLibraryFile ToolLibraryCsv::fromCsv(const QByteArray& text) {
  ToolLibraryFile out;
  QString all = QString::fromUtf8(text);
  if (all.startsWith(QChar(0xFEFF))) all.remove(0, 1);
  const QStringList lines = all.split('\n');
  CsvReader reader;
  bool header = false;
  QStringList cells;
  for (qsizetype i = 0; i < lines.size(); ++i) {
    const int lineNo = static_cast<int>(i + 1);
    QString line = lines[i];
    if (line.endsWith('\r')) line.chop(1);
    if (line.trimmed().isEmpty() || line.trimmed().startsWith('#')) continue;
    if (!splitCsvLine(line, cells)) {
      out.error = QString("line %1, column %2: unterminated quoted field").arg(lineNo).arg(cells.size());
      break;
    }
    const bool ok = header ? reader.readRow(lineNo, cells, out) : reader.readHeader(lineNo, cells);
    if (!ok) {
      out.error = reader.error;
      break;
    }
    if (!header) out.idColumn = static_cast<int>(cells.indexOf("tool_id")) + 1;
    header = true;
  }
  if (out.error.isEmpty() && !header) out.error = "line 1: missing header row (" + columns().join(',') + ")";
  if (!out.ok()) {
    out.tools.clear();
    out.lines.clear();
  }
  return out;
}

QByteArray ToolLibraryCsv::toJson(const std::vector<ToolSpec>& tools) {
  Project p;
  p.name = "Tool library";
  p.tools = tools;
  p.document.insert("tools", QJsonArray());  // written even when empty: fromJson requires the key
  return formatProjectJson(projectToJson(p));
}

ToolLibraryFile ToolLibraryCsv::fromJson(const QByteArray& text) {
  ToolLibraryFile out;
  try {
    out.tools = toolsFromJson(text);
    out.lines.assign(out.tools.size(), 0);
  } catch (const ProjectError& e) {
    out.error = QString::fromStdString(e.what());
  }
  return out;
}

QString ToolLibraryCsv::merge(const Project& base, const ToolLibraryFile& file, bool replace, Project& merged) {
  if (!file.ok()) return file.error;
  Project p = base;
  if (replace) p.tools.clear();
  const std::size_t offset = p.tools.size();
  QSet<QString> existing;
  for (const ToolSpec& t : p.tools) existing.insert(t.id);
  for (std::size_t i = 0; i < file.tools.size(); ++i) {
    if (existing.contains(file.tools[i].id)) {
      const QString where = file.lines[i] > 0
                                ? QString("line %1, column %2 (tool_id): ").arg(file.lines[i]).arg(file.idColumn)
                                : QString("tools[%1].id: ").arg(i);
      return where + QString("'%1' duplicate tool id (already in the library)").arg(file.tools[i].id);
    }
    p.tools.push_back(file.tools[i]);
  }
  QString error = projectValidationError(p);
  if (!error.isEmpty()) {
    // Name the file's line when the rule concerns an imported tool.
    const QRegularExpressionMatch m = QRegularExpression(R"(tools\[(\d+)\])").match(error);
    const qsizetype index = m.hasMatch() ? m.captured(1).toLongLong() - static_cast<qsizetype>(offset) : -1;
    if (index >= 0 && index < static_cast<qsizetype>(file.lines.size()) && file.lines[std::size_t(index)] > 0)
      return QString("line %1: %2").arg(file.lines[std::size_t(index)]).arg(error);
    return "the imported tools do not fit the project: " + error;
  }
  merged = p;
  return {};
}

QString ToolLibraryCsv::writeFile(const QString& path, const QByteArray& bytes) {
  const QString error = writeFileAtomically(path, bytes);
  return error.isEmpty() ? QString() : QString("%1: cannot write (%2)").arg(path, error);
}

QString ToolLibraryCsv::readFile(const QString& path, QByteArray& bytes) {
  try {
    bytes = readBoundedFile(path, kToolLibraryFileLimit);
  } catch (const InvalidInput& e) {
    return QString("%1: %2").arg(path, QString::fromStdString(e.what()));
  }
  return {};
}

}  // namespace mx::app
