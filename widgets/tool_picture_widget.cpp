#include "tool_picture_widget.h"

#include <QPainter>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "document/tool_geometry.h"

namespace mx::widgets {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr double kPitchLabelRadius = 0.62;  // of the circle's radius
constexpr double kRunoutShownAs = 0.12;     // the largest runout, as a fraction of the radius

// Clockwise from the top of the screen.
QPointF onCircle(QPointF centre, double radius, double angle_rad) {
  return centre + QPointF(radius * std::sin(angle_rad), -radius * std::cos(angle_rad));
}

QString degrees(double value) {
  return QString::number(value, 'g', 4) + QChar(0x00b0);
}

QString listText(const std::vector<double>& values, double factor, const QString& unit) {
  QStringList items;
  for (double v : values) items << QString::number(v * factor, 'g', 4) + unit;
  return items.join(", ");
}

}  // namespace

QStringList toolCaption(const MillingSetup& c, double runout_gain, const DisplayUnits* units) {
  const QString teeth = c.teeth == 1 ? QObject::tr("1 tooth") : QObject::tr("%1 teeth").arg(c.teeth);
  const double diameter_mm = c.diameter_m * 1e3;
  QStringList lines{QObject::tr("%1: %2, D = %3 %4")
                        .arg(QString::fromStdString(c.tool_id), teeth)
                        .arg(units ? units->fromMm(diameter_mm) : diameter_mm, 0, 'g', 4)
                        .arg(units ? units->lengthSuffix() : QStringLiteral("mm"))};
  lines << (c.uniformPitch() ? QObject::tr("uniform pitch %1").arg(degrees(c.toothPitchRad() * kDegPerRad))
                             : QObject::tr("pitch: %1").arg(listText(c.pitch_rad, kDegPerRad, QChar(0x00b0))));
  lines << (c.helix_rad != 0.0 ? QObject::tr("helix %1 (blue: lag at z = R)").arg(degrees(c.helix_rad * kDegPerRad))
                               : QObject::tr("straight teeth (helix 0\u00b0)"));
  if (c.hasRunout())
    lines << QObject::tr("runout: %1 \u00b5m (drawn \u00d7%2)")
                 .arg(listText(c.runout_m, 1e6, QString()))
                 .arg(runout_gain, 0, 'f', 0);
  lines << QObject::tr("rotation: clockwise");
  return lines;
}

namespace {

// The helix lag of each edge at height R above the tip, drawn as an arc behind the tooth.
void drawHelixLag(QPainter& p, const MillingSetup& c, const QRectF& circle) {
  const double lag_deg = std::tan(c.helix_rad) * kDegPerRad;
  p.setPen(QPen(QColor(0, 110, 200, 150), 3));
  for (int j = 0; j < c.teeth; ++j) {
    const double qt_start = 90.0 - c.toothAngleRad(j) * kDegPerRad;  // Qt: counterclockwise from 3 o'clock
    p.drawArc(circle, qRound(qt_start * 16), qRound(lag_deg * 16));
  }
}

void drawRotationArrow(QPainter& p, QPointF centre, double radius) {
  const QRectF ring(centre - QPointF(radius, radius), centre + QPointF(radius, radius));
  p.setPen(QPen(Qt::darkGray, 1.2));
  p.drawArc(ring, 16 * 60, -16 * 40);  // from 30 deg to 70 deg clockwise of the top
  const QPointF tip = onCircle(centre, radius, 70.0 / kDegPerRad);
  const QPointF back = onCircle(centre, radius, 62.0 / kDegPerRad);
  const QPointF side = (tip - centre) / radius * 4.0;
  p.drawPolygon(QPolygonF{tip, back + side, back - side});
}

}  // namespace

std::vector<ToothMark> toothMarks(const MillingSetup& cutter, QPointF centre, double radius_px,
                                  double runout_px_per_m) {
  std::vector<ToothMark> marks;
  for (int j = 0; j < cutter.teeth; ++j) {
    ToothMark m;
    m.angle_rad = cutter.toothAngleRad(j);
    m.pitch_deg = cutter.pitchRad(j) * kDegPerRad;
    m.edge = onCircle(centre, radius_px + cutter.runoutM(j) * runout_px_per_m, m.angle_rad);
    m.pitch_label = onCircle(centre, kPitchLabelRadius * radius_px, m.angle_rad + 0.5 * cutter.pitchRad(j));
    marks.push_back(m);
  }
  return marks;
}

double runoutScalePxPerM(const MillingSetup& cutter, double max_px) {
  double largest = 0.0;
  for (int j = 0; j < cutter.teeth; ++j) largest = std::max(largest, std::abs(cutter.runoutM(j)));
  return largest > 0.0 ? max_px / largest : 0.0;
}

ToolPictureWidget::ToolPictureWidget(QWidget* parent) : QWidget(parent) {
  setToolTip(
      tr("End view of the selected tool, looking at its tip: the teeth at their pitch angles "
         "(rotation clockwise), the helix lag and the runout (exaggerated)"));
}

void ToolPictureWidget::setTool(const app::ToolSpec& tool) {
  cutter_ = app::cutterGeometryOf(tool);
  update();
}

void ToolPictureWidget::setUnits(const DisplayUnits* units) {
  units_ = units;
  if (units) connect(units, &DisplayUnits::changed, this, qOverload<>(&QWidget::update));
  update();
}

void ToolPictureWidget::clear() {
  cutter_.reset();
  update();
}

// The end view on the left (a square), the description on the right.
void ToolPictureWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  p.fillRect(rect(), palette().base());
  p.setPen(palette().text().color());
  const QFontMetrics fm(font());
  if (!cutter_ || cutter_->teeth < 1) {
    p.drawText(rect(), Qt::AlignCenter, tr("No tool selected"));
    return;
  }
  const MillingSetup& c = *cutter_;
  const double side = std::min<double>(height(), 0.55 * width());
  const double margin = fm.height() * 1.9;  // the tooth numbers and the rotation arrow
  const double radius = std::max(10.0, 0.5 * side - margin);
  const QPointF centre(0.5 * side, 0.5 * height());
  const double scale = runoutScalePxPerM(c, kRunoutShownAs * radius);

  const QRectF circle(centre - QPointF(radius, radius), centre + QPointF(radius, radius));
  p.setPen(QPen(palette().text().color(), 1.5));
  p.setBrush(QColor(200, 200, 205, 90));
  p.drawEllipse(circle);
  p.setBrush(Qt::NoBrush);
  if (c.helix_rad != 0.0) drawHelixLag(p, c, circle.adjusted(4, 4, -4, -4));
  drawRotationArrow(p, centre, radius + fm.height() * 1.3);

  const std::vector<ToothMark> marks = toothMarks(c, centre, radius, scale);
  for (std::size_t j = 0; j < marks.size(); ++j) {
    const ToothMark& m = marks[j];
    p.setPen(QPen(QColor(200, 60, 20), 2.5));
    p.drawLine(onCircle(centre, 0.2 * radius, m.angle_rad), m.edge);
    p.setBrush(QColor(200, 60, 20));
    p.drawEllipse(m.edge, 3.5, 3.5);
    p.setBrush(Qt::NoBrush);
    p.setPen(palette().text().color());
    const QPointF number = onCircle(centre, radius + 0.55 * fm.height() + 6.0, m.angle_rad);
    p.drawText(QRectF(number - QPointF(fm.height(), 0.5 * fm.height()), QSizeF(2 * fm.height(), fm.height())),
               Qt::AlignCenter, QString::number(j + 1));
    if (c.teeth > 1) {
      const QString label = degrees(m.pitch_deg);
      const QRectF box(m.pitch_label - QPointF(0.5 * fm.horizontalAdvance(label) + 2, 0.5 * fm.height()),
                       QSizeF(fm.horizontalAdvance(label) + 4, fm.height()));
      p.drawText(box, Qt::AlignCenter, label);
    }
  }
  const QRectF text(side + 6, 4, width() - side - 10, height() - 8);
  p.drawText(text, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap,
             toolCaption(c, scale * c.diameter_m / (2.0 * radius), units_).join("\n"));
}

}  // namespace mx::widgets
