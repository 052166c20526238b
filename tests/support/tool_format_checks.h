#pragma once
// Checks shared by the tool-library format tests: tools compared field by field (the first differing
// tool is printed as project JSON), and the message of a refused import.
#include <QJsonDocument>
#include <QtTest>
#include <functional>
#include <vector>

#include "document/project.h"
#include "services/tool_formats/tool_library_io.h"

namespace mx::test {

// A tool as a CAM library gives it: no dynamics.
inline app::ToolSpec newTool(const QString& id, const QString& type, double diameter, int teeth) {
  app::ToolSpec tool;
  tool.id = id;
  tool.type = type;
  tool.diameter_mm = diameter;
  tool.teeth = teeth;
  return tool;
}

inline QByteArray toolText(const app::ToolSpec& tool) {
  return QJsonDocument(app::toolToJson(tool)).toJson(QJsonDocument::Compact);
}

// True when equal; else prints the first difference and returns false (for QVERIFY).
inline bool sameTools(const std::vector<app::ToolSpec>& got, const std::vector<app::ToolSpec>& expected) {
  if (got.size() != expected.size()) {
    qWarning("%zu tools, expected %zu", got.size(), expected.size());
    return false;
  }
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (got[i] == expected[i]) continue;
    qWarning("tool %zu differs:\n  got      %s\n  expected %s", i, toolText(got[i]).constData(),
             toolText(expected[i]).constData());
    return false;
  }
  return true;
}

// The tools without their origin records (an edited tool's record changes with the export).
inline std::vector<app::ToolSpec> withoutOrigins(std::vector<app::ToolSpec> tools) {
  for (app::ToolSpec& tool : tools) tool.origin.reset();
  return tools;
}

// The message of the ToolLibraryError `action` throws; empty (and a warning) when it throws none.
inline QString refusal(const std::function<void()>& action) {
  try {
    action();
  } catch (const app::ToolLibraryError& e) {
    return QString::fromUtf8(e.what());
  }
  qWarning("accepted");
  return {};
}

}  // namespace mx::test
