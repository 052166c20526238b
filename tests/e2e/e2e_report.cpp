#include "e2e_report.h"

#include <QTextStream>
#include <cmath>
#include <cstdio>

namespace mx::e2e {

namespace {
QTextStream& out() {
  static QTextStream stream(stdout);
  return stream;
}

QString number(double v) {
  return QString::number(v, 'g', 10);
}
}  // namespace

bool Report::check(const QString& name, bool ok, const QString& detail) {
  out() << (ok ? "ok    " : "FAIL  ") << name << ": " << detail << Qt::endl;
  if (ok)
    ++passed_;
  else
    failed_ << name + ": " + detail;
  return ok;
}

bool Report::near(const QString& name, double actual, double expected, double abs_tol, double rel_tol,
                  const QString& unit) {
  bool ok = false;
  if (std::isnan(actual) || std::isnan(expected))
    ok = std::isnan(actual) && std::isnan(expected);
  else if (std::isinf(actual) || std::isinf(expected))
    ok = actual == expected;
  else
    ok = std::abs(actual - expected) <= abs_tol + rel_tol * std::abs(expected);
  const QString u = unit.isEmpty() ? QString() : " " + unit;
  QString tolerance = number(abs_tol) + u;
  if (rel_tol > 0.0) tolerance += QString(" + %1 relative").arg(number(rel_tol));
  return check(name, ok,
               QString("GUI %1%2, expected %3%2 (tolerance %4)").arg(number(actual), u, number(expected), tolerance));
}

void Report::require(const QString& name, bool ok, const QString& detail) {
  if (!check(name, ok, detail)) throw Aborted(name + ": " + detail);
}

void Report::note(const QString& text) {
  out() << "      " << text << Qt::endl;
}

void Report::abort(const QString& message) {
  out() << "FAIL  " << message << Qt::endl;
  failed_ << message;
}

}  // namespace mx::e2e
