#pragma once
// Human-friendly JSON text for project files: the project's known keys in their documented order
// (format, version, name, ... ; id, teeth, diameter_mm, ...), unknown keys after them alphabetically;
// short objects and arrays on one line, as in the hand-written examples. Scalars are written by
// QJsonDocument, so numbers and strings round-trip exactly.
#include <QByteArray>
#include <QJsonObject>

namespace mx::app {

QByteArray formatProjectJson(const QJsonObject& root);

}  // namespace mx::app
