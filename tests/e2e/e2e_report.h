#pragma once
// The verdicts of an end-to-end scenario. Each check prints one line, "ok" or "FAIL", with its name
// and the values compared; require() stops the scenario (Aborted) when what follows cannot run.
#include <QString>
#include <QStringList>
#include <stdexcept>

namespace mx::e2e {

// A check that stops the scenario: the message names it.
class Aborted : public std::runtime_error {
 public:
  explicit Aborted(const QString& message) : std::runtime_error(message.toStdString()) {}
};

class Report {
 public:
  bool check(const QString& name, bool ok, const QString& detail);
  // |actual - expected| <= abs_tol + rel_tol * |expected| (both NaN or both the same infinity pass).
  bool near(const QString& name, double actual, double expected, double abs_tol, double rel_tol,
            const QString& unit = {});
  void require(const QString& name, bool ok, const QString& detail);
  void note(const QString& text);
  void abort(const QString& message);  // a check that could not run

  int failures() const { return static_cast<int>(failed_.size()); }
  const QStringList& failed() const { return failed_; }
  int passed() const { return passed_; }

 private:
  QStringList failed_;
  int passed_ = 0;
};

}  // namespace mx::e2e
