#pragma once
// Editor of the adaptive controller's settings: RLS (forgetting factor lambda, P(0), theta(0), the
// covariance reset rule and its threshold), the reference model (xi, T_r), the cutting time constant
// tau_c, the feed limit and the force reference. Each field is checked when its editing finishes; an
// invalid entry is refused in place with the reason ("Forgetting factor λ [–] = 0.3: must be in
// (0.5, 1]"), keeps its text in red for correction and changes nothing. A valid change emits
// settingsEdited with every field's last valid value; setSettings() emits nothing. The feed limit and
// the force reference are shown and typed in the shop units of setUnits() (the settings stay in mm/s, N).
#include <QHash>
#include <QPointer>
#include <QString>
#include <QWidget>
#include <optional>

#include "control_data.h"
#include "display_units.h"

class QComboBox;
class QLabel;
class QLineEdit;

namespace mx::widgets {

class ControlSettingsEditor : public QWidget {
  Q_OBJECT
 public:
  // Field keys: "lambda", "p0", "theta0", "reset_fraction" (shown in %), "xi", "tr_periods", "tau_c_ms",
  // "feed_max_mm_s", "force_reference_n".
  static QStringList fieldKeys();

  explicit ControlSettingsEditor(QWidget* parent = nullptr);

  void setSettings(const ControllerSettingsView& s);  // no signal; clears the errors
  ControllerSettingsView settings() const { return settings_; }

  // The displayed value of a field for a value in settings units ("1e+05" for P(0), "5" for a
  // reset fraction of 0.05); and the check of a typed text: the value in settings units, or the reason.
  // Without `units`: metric (mm/min, N).
  static QString format(const QString& key, double value, const ShopUnits& units = ShopUnits::metric());
  static std::optional<double> parse(const QString& key, const QString& text, QString* reason,
                                     const ShopUnits& units = ShopUnits::metric());
  void setUnits(DisplayUnits* units);  // nullptr: metric

  QLineEdit* field(const QString& key) const { return fields_.value(key, nullptr); }
  QComboBox* resetCombo() const { return reset_; }
  QString errorText() const;

 signals:
  void settingsEdited(const mx::widgets::ControllerSettingsView& s);

 private:
  void commit(const QString& key);
  void showSettings();
  void showErrors();
  const ShopUnits& shopUnits() const;

  QPointer<DisplayUnits> units_;
  QHash<QString, QLabel*> labels_;
  ControllerSettingsView settings_;
  QHash<QString, QLineEdit*> fields_;
  QHash<QString, QString> errors_;
  QComboBox* reset_;
  QLabel* error_label_;
};

}  // namespace mx::widgets
