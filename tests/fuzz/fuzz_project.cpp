// Fuzz target of the project file (.mxproj): JSON bytes read as loadProject reads them, then
// projectFromJson (the typed parse and validateProject). Bad input ends in a JSON syntax error, a
// top level that is not an object, or a ProjectError. A project that is accepted keeps the format's
// promises: it writes back (projectToJson, formatProjectJson) with finite numbers only, and that text
// reads again to the same project and the same text.
#include <QByteArray>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstdint>
#include <optional>

#include "document/json_format.h"
#include "document/project.h"
#include "document/project_validation.h"
#include "fuzz_check.h"

namespace {

using mx::fuzz::require;

std::optional<QJsonObject> jsonObject(const QByteArray& text) {
  QJsonParseError error{};
  const QJsonDocument document = QJsonDocument::fromJson(text, &error);
  if (error.error != QJsonParseError::NoError || !document.isObject()) return std::nullopt;
  return document.object();
}

void requireFiniteNumbers(const QJsonValue& value) {
  if (value.isDouble()) mx::fuzz::requireFinite(value.toDouble(), "the written project holds finite numbers only");
  if (value.isArray())
    for (const auto& element : value.toArray()) requireFiniteNumbers(element);
  if (value.isObject())
    for (const auto& member : value.toObject()) requireFiniteNumbers(member);
}

void checkRoundTrip(const mx::app::Project& project) {
  const QJsonObject written = mx::app::projectToJson(project);
  requireFiniteNumbers(written);
  const QByteArray text = mx::app::formatProjectJson(written);
  const std::optional<QJsonObject> root = jsonObject(text);
  require(root.has_value(), "the written project is a JSON object");
  try {
    const mx::app::Project reread = mx::app::projectFromJson(*root);
    const QJsonObject rewritten = mx::app::projectToJson(reread);
    require(rewritten == written, "the written project reads back to the same project");
    require(mx::app::formatProjectJson(rewritten) == text, "the written project writes the same text again");
    mx::app::validateProject(reread);
  } catch (const mx::app::ProjectError& e) {
    std::fprintf(stderr, "fuzz: %s\n", e.what());
    mx::fuzz::brokenPromise("the written project is refused");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<QJsonObject> root =
      jsonObject(QByteArray(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size)));
  if (!root) return 0;
  mx::app::Project project;
  try {
    project = mx::app::projectFromJson(*root);
  } catch (const mx::app::ProjectError&) {
    return 0;
  }
  checkRoundTrip(project);
  return 0;
}
