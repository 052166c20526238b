#pragma once
// Test helper: applies path mutations to a JSON document. "a/0/b=JSON" sets a value (JSON may also
// be inf, -inf or nan, which exist only in memory), "-a/0/b" removes it.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>
#include <QtGlobal>
#include <limits>
#include <optional>

namespace mx::test {

inline QJsonValue parseMutationValue(const QString& text) {
  if (text == "inf") return std::numeric_limits<double>::infinity();
  if (text == "-inf") return -std::numeric_limits<double>::infinity();
  if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
  QJsonParseError error;
  const QJsonDocument d = QJsonDocument::fromJson("[" + text.toUtf8() + "]", &error);
  if (error.error != QJsonParseError::NoError) qFatal("bad mutation value %s", qPrintable(text));
  return d.array().at(0);
}

inline QJsonValue setAt(const QJsonValue& node, QStringList path, const std::optional<QJsonValue>& value) {
  const QString head = path.takeFirst();
  if (node.isArray()) {
    QJsonArray a = node.toArray();
    const int i = head.toInt();
    if (path.isEmpty() && !value) {
      a.removeAt(i);
    } else {
      a[i] = path.isEmpty() ? *value : setAt(a.at(i), path, value);
    }
    return a;
  }
  QJsonObject o = node.toObject();
  if (path.isEmpty() && !value) {
    o.remove(head);
  } else {
    o[head] = path.isEmpty() ? *value : setAt(o.value(head), path, value);
  }
  return o;
}

inline QJsonObject mutated(QJsonObject root, const QStringList& mutations) {
  for (const QString& m : mutations) {
    if (m.startsWith('-')) {
      root = setAt(root, m.mid(1).split('/'), std::nullopt).toObject();
    } else {
      const qsizetype eq = m.indexOf('=');
      root = setAt(root, m.left(eq).split('/'), parseMutationValue(m.mid(eq + 1))).toObject();
    }
  }
  return root;
}

}  // namespace mx::test

// The project at `source` with `mutations` applied, written to `target`; returns target.
#include <QFile>
namespace mx::test {
inline QString writeMutatedProject(const QString& source, const QStringList& mutations, const QString& target) {
  QFile in(source);
  if (!in.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(source));
  const QJsonObject root = mutated(QJsonDocument::fromJson(in.readAll()).object(), mutations);
  QFile out(target);
  if (!out.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(target));
  out.write(QJsonDocument(root).toJson());
  return target;
}
}  // namespace mx::test
