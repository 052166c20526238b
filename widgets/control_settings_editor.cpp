#include "control_settings_editor.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <cmath>

#include "indicator_gauge.h"

namespace mx::widgets {

namespace {

struct FieldSpec {
  const char* key;
  const char* label;  // %1: the shop unit of `quantity`
  const char* tip;
  double min, max;
  bool min_open;                                    // min itself refused
  double display_scale;                             // displayed = value * scale (min and max are displayed values)
  std::optional<Quantity> quantity = std::nullopt;  // shown in this shop unit: value * to_base is in base units
  double to_base = 1.0;
};

// The limits are those of the engine's settings check.
constexpr FieldSpec kFields[] = {
    {"lambda", "Forgetting factor \u03bb [\u2013]", "RLS forgetting factor (eq. 26); 1: no forgetting", 0.5, 1.0, true,
     1.0},
    {"p0", "Initial covariance P(0) [\u2013]", "RLS covariance P(0) = P0 I, also the value after a reset", 1.0, 1e9,
     false, 1.0},
    {"theta0", "Initial estimates \u03b8(0) [\u2013]", "Initial value of every estimated parameter (paper: 0.2)", -1e6,
     1e6, false, 1.0},
    {"reset_fraction", "Reset threshold [% of F_r]",
     "Covariance reset when the a-priori prediction error exceeds this fraction of the force reference", 0.0, 100.0,
     true, 100.0},
    {"xi", "Model damping \u03be [\u2013]", "Damping ratio of the reference model (paper: 0.75)", 0.1, 2.0, false, 1.0},
    {"tr_periods", "Model rise time T_r [spindle periods]", "Rise time of the reference model (paper: 4 periods)", 1.0,
     50.0, false, 1.0},
    {"tau_c_ms", "Cutting time constant \u03c4_c [ms] (0 = default)",
     "Time constant of the cutting process; 0 takes half a tooth period", 0.0, 1e4, false, 1.0},
    {"feed_max_mm_s", "Feed limit f_max [%1]", "Feed-drive maximum; the control law is clamped to [0, f_max]", 0.0, 1e4,
     true, 1.0, Quantity::Feed, 60.0},  // mm/s, shown per minute
    {"force_reference_n", "Force reference F_r [%1]", "Force the controller holds (paper: 1200 N)", 0.0, 1e6, true, 1.0,
     Quantity::Force},
};

QString label(const FieldSpec& f, const ShopUnits& units) {
  const QString text = ControlSettingsEditor::tr(f.label);
  return f.quantity ? text.arg(units.symbol(*f.quantity)) : text;
}

// A settings value as displayed, and back.
double shown(const FieldSpec& f, double value, const ShopUnits& units) {
  return f.quantity ? units.fromBase(*f.quantity, value * f.to_base) : value * f.display_scale;
}
double fromShown(const FieldSpec& f, double displayed, const ShopUnits& units) {
  return f.quantity ? units.toBase(*f.quantity, displayed) / f.to_base : displayed / f.display_scale;
}

const FieldSpec* spec(const QString& key) {
  for (const FieldSpec& f : kFields)
    if (key == QLatin1String(f.key)) return &f;
  return nullptr;
}

double* member(ControllerSettingsView& s, const QString& key) {
  if (key == "lambda") return &s.lambda;
  if (key == "p0") return &s.p0;
  if (key == "theta0") return &s.theta0;
  if (key == "reset_fraction") return &s.reset_fraction;
  if (key == "xi") return &s.xi;
  if (key == "tr_periods") return &s.tr_periods;
  if (key == "tau_c_ms") return &s.tau_c_ms;
  if (key == "feed_max_mm_s") return &s.feed_max_mm_s;
  if (key == "force_reference_n") return &s.force_reference_n;
  return nullptr;
}

QString number(double v) {
  return QLocale::c().toString(v, 'g', 6);
}

}  // namespace

QStringList ControlSettingsEditor::fieldKeys() {
  QStringList keys;
  for (const FieldSpec& f : kFields) keys << QString::fromLatin1(f.key);
  return keys;
}

QString ControlSettingsEditor::format(const QString& key, double value, const ShopUnits& units) {
  const FieldSpec* f = spec(key);
  if (!f) return {};
  if (key == "p0") {  // scientific, trailing zeros of the mantissa dropped: "1e+05", "2.5e+06"
    QString text = QLocale::c().toString(value, 'e', 5);
    const qsizetype e = text.indexOf(QLatin1Char('e'));
    QString mantissa = text.left(e);
    while (mantissa.endsWith(QLatin1Char('0'))) mantissa.chop(1);
    if (mantissa.endsWith(QLatin1Char('.'))) mantissa.chop(1);
    return mantissa + text.mid(e);
  }
  return number(shown(*f, value, units));
}

std::optional<double> ControlSettingsEditor::parse(const QString& key, const QString& text, QString* reason,
                                                   const ShopUnits& units) {
  const FieldSpec* f = spec(key);
  auto refuse = [&](const QString& why) -> std::optional<double> {
    if (reason)
      *reason = tr("%1 = %2: %3")
                    .arg(f ? label(*f, units) : key, text.trimmed().isEmpty() ? tr("(empty)") : text.trimmed(), why);
    return std::nullopt;
  };
  if (!f) return refuse(tr("unknown field"));
  bool ok = false;
  double typed = QLocale::c().toDouble(text.trimmed(), &ok);
  if (!ok) typed = QLocale().toDouble(text.trimmed(), &ok);
  if (!ok || !std::isfinite(typed)) return refuse(tr("not a number"));
  // The limits as displayed: converted for a shop-unit field.
  const double lo = f->quantity ? shown(*f, f->min, units) : f->min;
  const double hi = f->quantity ? shown(*f, f->max, units) : f->max;
  const bool below = f->min_open ? typed <= lo : typed < lo;
  if (below || typed > hi)
    return refuse(tr("must be in %1%2, %3]").arg(f->min_open ? "(" : "[", number(lo), number(hi)));
  return fromShown(*f, typed, units);
}

void ControlSettingsEditor::setUnits(DisplayUnits* units) {
  const auto apply = [this] {
    for (const FieldSpec& f : kFields) labels_[QString::fromLatin1(f.key)]->setText(label(f, shopUnits()) + ":");
    showSettings();
  };
  followUnits(this, units_, units, apply);
}

const ShopUnits& ControlSettingsEditor::shopUnits() const {
  return DisplayUnits::of(units_);
}

ControlSettingsEditor::ControlSettingsEditor(QWidget* parent)
    : QWidget(parent), reset_(new QComboBox(this)), error_label_(new QLabel(this)) {
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  auto* form = new QFormLayout;
  form->setLabelAlignment(Qt::AlignRight);
  outer->addLayout(form);
  reset_->setObjectName(QStringLiteral("control_reset"));
  reset_->addItem(tr("None"));
  reset_->addItem(tr("A-priori error > threshold \u00d7 F_r"));
  reset_->addItem(tr("Trace of P outside [min, max]"));
  reset_->setToolTip(tr("When the RLS covariance is reset to P(0) (paper: the 5 % error criterion)"));
  for (const FieldSpec& f : kFields) {
    const QString key = QString::fromLatin1(f.key);
    auto* edit = new QLineEdit(this);
    edit->setObjectName(QStringLiteral("control_") + key);
    edit->setToolTip(tr(f.tip));
    edit->setAlignment(Qt::AlignRight);
    auto* name = new QLabel(label(f, shopUnits()) + ":", this);
    name->setToolTip(tr(f.tip));
    name->setBuddy(edit);
    if (key == "reset_fraction") form->addRow(tr("Covariance reset:"), reset_);
    form->addRow(name, edit);
    labels_.insert(key, name);
    fields_.insert(key, edit);
    connect(edit, &QLineEdit::editingFinished, this, [this, key] { commit(key); });
  }
  connect(reset_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index < 0 || index == settings_.reset) return;
    settings_.reset = index;
    fields_["reset_fraction"]->setEnabled(index == 1);
    emit settingsEdited(settings_);
  });
  error_label_->setObjectName(QStringLiteral("control_settings_error"));
  error_label_->setWordWrap(true);
  error_label_->setStyleSheet(QString("QLabel { color: %1; }").arg(IndicatorGauge::alarmColor().name()));
  outer->addWidget(error_label_);
  setSettings(ControllerSettingsView{});
}

void ControlSettingsEditor::setSettings(const ControllerSettingsView& s) {
  settings_ = s;
  errors_.clear();
  showSettings();
  showErrors();
}

void ControlSettingsEditor::showSettings() {
  for (auto it = fields_.cbegin(); it != fields_.cend(); ++it) {
    if (errors_.contains(it.key())) continue;  // keeps the refused text for correction
    it.value()->setText(format(it.key(), *member(settings_, it.key()), shopUnits()));
  }
  const QSignalBlocker block(reset_);
  reset_->setCurrentIndex(settings_.reset >= 0 && settings_.reset < reset_->count() ? settings_.reset : 0);
  fields_["reset_fraction"]->setEnabled(settings_.reset == 1);
}

void ControlSettingsEditor::commit(const QString& key) {
  QLineEdit* edit = fields_.value(key);
  double* target = member(settings_, key);
  if (edit->text() == format(key, *target, shopUnits())) {  // untouched: the shown value may be rounded
    errors_.remove(key);
    showErrors();
    return;
  }
  QString reason;
  const std::optional<double> value = parse(key, edit->text(), &reason, shopUnits());
  if (!value) {
    errors_.insert(key, reason);
    showErrors();
    return;
  }
  errors_.remove(key);
  const bool changed = *target != *value;
  *target = *value;
  edit->setText(format(key, *value, shopUnits()));
  showErrors();
  if (changed) emit settingsEdited(settings_);
}

void ControlSettingsEditor::showErrors() {
  for (auto it = fields_.cbegin(); it != fields_.cend(); ++it)
    it.value()->setStyleSheet(
        errors_.contains(it.key())
            ? QString("QLineEdit { border: 2px solid %1; }").arg(IndicatorGauge::alarmColor().name())
            : QString());
  error_label_->setText(errorText());
  error_label_->setVisible(!errors_.isEmpty());
}

QString ControlSettingsEditor::errorText() const {
  QStringList lines;
  for (const QString& key : fieldKeys())
    if (errors_.contains(key)) lines << errors_.value(key);
  return lines.join('\n');
}

}  // namespace mx::widgets
