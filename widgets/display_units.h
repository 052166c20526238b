#pragma once
// Display units for lengths (mm or inch). The engine stays SI and the project file in mm; only what
// the views show and accept changes. One instance per main window, shared by its views.
#include <QObject>
#include <QString>

namespace mx::widgets {

class DisplayUnits : public QObject {
  Q_OBJECT
 public:
  enum class Length { Millimetre, Inch };
  explicit DisplayUnits(QObject* parent = nullptr) : QObject(parent) {}

  Length length() const { return length_; }
  void setLength(Length length) {
    if (length == length_) return;
    length_ = length;
    emit changed();
  }
  // mm -> display value and back.
  double fromMm(double mm) const { return length_ == Length::Inch ? mm / 25.4 : mm; }
  double toMm(double value) const { return length_ == Length::Inch ? value * 25.4 : value; }
  QString lengthSuffix() const { return length_ == Length::Inch ? QStringLiteral("in") : QStringLiteral("mm"); }
  int lengthDecimals() const { return length_ == Length::Inch ? 5 : 4; }

 signals:
  void changed();

 private:
  Length length_ = Length::Millimetre;
};

}  // namespace mx::widgets
