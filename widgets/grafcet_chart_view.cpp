#include "grafcet_chart_view.h"

#include <QFontMetricsF>
#include <QHelpEvent>
#include <QImage>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <algorithm>
#include <cmath>
#include <queue>

#include "grafcet_chart_layout.h"

namespace mx::widgets {

namespace {
using L = GrafcetLayout;
constexpr double kBarBelowStep = L::kBarBelowStep, kNameMaxW = L::kNameMaxW;
constexpr double kReceptivityMaxW = L::kReceptivityMaxW;
const QColor kInk = L::ink(), kActiveFill = L::activeFill(), kToken = L::token(), kBackArc = L::backArc();
const QColor kSelect(30, 110, 220);

QString transitionLabel(int id) {
  return QStringLiteral("(%1)").arg(id);
}
}  // namespace

GrafcetChartView::GrafcetChartView(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("grafcetChartView"));
  setAutoFillBackground(true);
  QPalette pal = palette();
  pal.setColor(QPalette::Window, Qt::white);
  setPalette(pal);
  layoutChart();
}

QSize GrafcetChartView::sizeHint() const {
  return QSize(static_cast<int>(std::ceil(content_.width())), static_cast<int>(std::ceil(content_.height())));
}

void GrafcetChartView::setChart(const GrafcetChartData& chart) {
  chart_ = chart;
  QList<int> kept;
  for (int id : std::as_const(active_))
    if (std::any_of(chart_.steps.begin(), chart_.steps.end(), [id](const auto& s) { return s.id == id; })) kept << id;
  active_ = kept;
  layoutChart();
  update();
}

void GrafcetChartView::setActiveSteps(const QList<int>& step_ids) {
  QList<int> ids;
  for (int id : step_ids)
    if (layout_.steps.contains(id) && !ids.contains(id)) ids << id;
  std::sort(ids.begin(), ids.end());
  if (ids == active_) return;
  active_ = ids;
  update();
  emit activeStepsChanged(active_);
}

QList<int> GrafcetChartView::activeSteps() const {
  return active_;
}

void GrafcetChartView::setSelected(int step_id, int transition_id) {
  selected_step_ = step_id;
  selected_transition_ = transition_id;
  update();
}

QRectF GrafcetChartView::stepRect(int step_id) const {
  return layout_.steps.contains(step_id) ? toWidget().mapRect(layout_.steps.value(step_id)) : QRectF();
}

QRectF GrafcetChartView::transitionRect(int transition_id) const {
  return layout_.transitions.contains(transition_id) ? toWidget().mapRect(layout_.transitions.value(transition_id).bar)
                                                     : QRectF();
}

void GrafcetChartView::setFitToWidget(bool fit) {
  fit_ = fit;
  layoutChart();
  update();
}

double GrafcetChartView::scale() const {
  if (!fit_ || content_.isEmpty()) return 1.0;
  return std::clamp(std::min(width() / content_.width(), height() / content_.height()), kMinFitScale, 1.0);
}

QTransform GrafcetChartView::toWidget() const {
  const double s = scale();
  return QTransform::fromScale(s, s);
}

bool GrafcetChartView::stepDrawnAsInitial(int step_id) const {
  for (const GrafcetStepView& s : chart_.steps)
    if (s.id == step_id) return s.initial && layout_.steps.contains(step_id);
  return false;
}

bool GrafcetChartView::isBackArc(int transition_id) const {
  return layout_.transitions.value(transition_id).back;
}

void GrafcetChartView::layoutChart() {
  layout_ = GrafcetLayout::compute(chart_, font());
  content_ = layout_.content;
  // Fit mode: never smaller than the least scale (a scroll area scrolls the rest).
  setMinimumSize(fit_ ? (content_ * kMinFitScale).toSize() : sizeHint());
  updateGeometry();
}

void GrafcetChartView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing, true);
  p.fillRect(rect(), Qt::white);
  p.setTransform(toWidget());
  paintChart(p);
}

void GrafcetChartView::paintChart(QPainter& p) const {
  L::paintHeader(p, font(), chart_.name.isEmpty() ? tr("Grafcet chart") : tr("Grafcet: %1").arg(chart_.name));
  paintArcs(p);
  const QFont id_font = L::font(font(), L::kIdPt, true), name_font = L::font(font(), L::kNamePt, false, true);
  const QFont text_font = L::font(font(), L::kTextPt), action_font = L::font(font(), L::kActionPt, true);
  // Transitions: bar, "(n)" on the left, receptivity on the right.
  for (const GrafcetTransitionView& t : chart_.transitions) {
    const QRectF bar = layout_.transitions.value(t.id).bar;
    if (t.id == selected_transition_)
      p.fillRect(bar.adjusted(-5, -5, 5, 5), QColor(kSelect.red(), kSelect.green(), kSelect.blue(), 70));
    p.fillRect(bar, kInk);
    p.setFont(text_font);
    p.setPen(kInk);
    const QRectF label(bar.left() - 108, bar.center().y() - 10, 100, 20);
    p.drawText(label, Qt::AlignRight | Qt::AlignVCenter, transitionLabel(t.id));
    const QFontMetricsF fm(text_font);
    const QString rec = fm.elidedText(t.receptivity, Qt::ElideRight, kReceptivityMaxW);
    p.drawText(QRectF(bar.right() + 8, bar.center().y() - 10, kReceptivityMaxW + 4, 20),
               Qt::AlignLeft | Qt::AlignVCenter, rec);
  }
  // Steps: box (double when initial), number, name on the left, actions on the right, token.
  for (const GrafcetStepView& s : chart_.steps) {
    const QRectF r = layout_.steps.value(s.id);
    if (r.isNull()) continue;
    const bool active = active_.contains(s.id);
    p.setPen(QPen(kInk, 1.6));
    p.setBrush(active ? kActiveFill : QColor(Qt::white));
    p.drawRect(r);
    if (s.initial) {
      p.setBrush(Qt::NoBrush);
      p.drawRect(r.adjusted(4, 4, -4, -4));
    }
    if (s.id == selected_step_) {
      p.setPen(QPen(kSelect, 3));
      p.setBrush(Qt::NoBrush);
      p.drawRect(r.adjusted(-5, -5, 5, 5));
    }
    p.setPen(kInk);
    p.setFont(id_font);
    p.drawText(r.adjusted(0, 4, 0, active ? -14 : 0), Qt::AlignCenter, QString::number(s.id));
    if (active) {
      p.setPen(Qt::NoPen);
      p.setBrush(kToken);
      p.drawEllipse(QPointF(r.center().x(), r.bottom() - 11), 5.5, 5.5);
    }
    p.setPen(QColor(70, 70, 70));
    p.setFont(name_font);
    p.drawText(QRectF(r.left() - 8 - kNameMaxW, r.top() - 4, kNameMaxW, r.height() + 8),
               Qt::AlignRight | Qt::AlignVCenter | Qt::TextWordWrap, s.name);
    double x = r.right() + 16;
    const QFontMetricsF afm(action_font);
    p.setFont(action_font);
    if (!s.actions.isEmpty()) {
      p.setPen(QPen(kInk, 1.2));
      p.drawLine(QPointF(r.right(), r.center().y()), QPointF(x, r.center().y()));
    }
    for (const QString& a : s.actions) {
      const double w = std::max(26.0, afm.horizontalAdvance(a) + 12);
      const QRectF box(x, r.center().y() - 13, w, 26);
      const bool impulse = a.endsWith(QLatin1Char('*'));
      p.setPen(QPen(kInk, 1.2));
      p.setBrush(active ? (impulse ? QColor(255, 210, 160) : QColor(200, 235, 200)) : QColor(Qt::white));
      p.drawRect(box);
      p.drawText(box, Qt::AlignCenter, a);
      x += w;
    }
  }
}

void GrafcetChartView::paintArcs(QPainter& p) const {
  QHash<int, QVector<int>> owned;  // step -> transitions whose bar hangs under it (by x)
  for (const GrafcetTransitionView& t : chart_.transitions) {
    const QRectF bar = layout_.transitions.value(t.id).bar;
    for (int f : t.from)
      if (layout_.steps.contains(f) && std::abs(layout_.steps[f].bottom() + kBarBelowStep - bar.top()) < 0.5)
        owned[f] << t.id;
  }
  p.setBrush(Qt::NoBrush);
  for (auto it = owned.cbegin(); it != owned.cend(); ++it) {  // step -> bars (OR divergence)
    const QRectF r = layout_.steps[it.key()];
    double lo = r.center().x(), hi = lo;
    for (int tid : it.value()) {
      lo = std::min(lo, layout_.transitions.value(tid).bar.center().x());
      hi = std::max(hi, layout_.transitions.value(tid).bar.center().x());
    }
    p.setPen(QPen(kInk, 1.4));
    const double y_div = r.bottom() + 12;
    p.drawLine(QPointF(r.center().x(), r.bottom()),
               QPointF(r.center().x(), hi > lo ? y_div : r.bottom() + kBarBelowStep));
    if (hi > lo) {
      p.drawLine(QPointF(lo, y_div), QPointF(hi, y_div));
      for (int tid : it.value()) {
        const QRectF bar = layout_.transitions.value(tid).bar;
        p.drawLine(QPointF(bar.center().x(), y_div), QPointF(bar.center().x(), bar.top()));
      }
    }
  }
  for (const GrafcetTransitionView& t : chart_.transitions) {
    const L::Transition g = layout_.transitions.value(t.id);
    const QRectF bar = g.bar;
    // Extra sources (parallel convergence): a double line above the bar.
    QVector<int> others;
    for (int f : t.from)
      if (layout_.steps.contains(f) && !owned.value(f).contains(t.id)) others << f;
    p.setPen(QPen(kInk, 1.4));
    if (!others.isEmpty()) {
      double lo = bar.center().x(), hi = lo;
      for (int f : others) {
        const QRectF r = layout_.steps[f];
        lo = std::min(lo, r.center().x());
        hi = std::max(hi, r.center().x());
        p.drawLine(QPointF(r.center().x(), r.bottom()), QPointF(r.center().x(), bar.top() - 14));
      }
      p.drawLine(QPointF(lo, bar.top() - 14), QPointF(hi, bar.top() - 14));
      p.drawLine(QPointF(lo, bar.top() - 10), QPointF(hi, bar.top() - 10));
      p.drawLine(QPointF(bar.center().x(), bar.top() - 10), QPointF(bar.center().x(), bar.top()));
    }
    QVector<int> targets;
    for (int to : t.to)
      if (layout_.steps.contains(to)) targets << to;
    if (targets.isEmpty()) continue;
    const QPointF start(bar.center().x(), bar.bottom());
    if (g.back) {
      p.setPen(QPen(kBackArc, 1.4));
      const double lx = layout_.laneX(g.lane);
      double top_y = g.depart_y;
      p.drawLine(start, QPointF(start.x(), g.depart_y));
      p.drawLine(QPointF(start.x(), g.depart_y), QPointF(lx, g.depart_y));
      for (int to : targets) {
        const QRectF r = layout_.steps[to];
        const double entry = r.top() - 14 - 6 * std::min(3, g.lane % 4);
        top_y = std::min(top_y, entry);
        p.drawLine(QPointF(lx, entry), QPointF(r.center().x(), entry));
        p.drawLine(QPointF(r.center().x(), entry), QPointF(r.center().x(), r.top()));
      }
      p.drawLine(QPointF(lx, g.depart_y), QPointF(lx, top_y));
      L::arrowUp(p, QPointF(lx, (g.depart_y + top_y) / 2 - 4));
      continue;
    }
    double lo = start.x(), hi = lo;
    for (int to : targets) {
      lo = std::min(lo, layout_.steps[to].center().x());
      hi = std::max(hi, layout_.steps[to].center().x());
    }
    if (targets.size() > 1) {  // parallel divergence: a double line under the bar
      const double y = bar.bottom() + 10;
      p.drawLine(start, QPointF(start.x(), y));
      p.drawLine(QPointF(lo, y), QPointF(hi, y));
      p.drawLine(QPointF(lo, y + 4), QPointF(hi, y + 4));
      for (int to : targets)
        p.drawLine(QPointF(layout_.steps[to].center().x(), y + 4),
                   QPointF(layout_.steps[to].center().x(), layout_.steps[to].top()));
      continue;
    }
    const QRectF r = layout_.steps[targets.front()];
    const double bend = r.top() - 6;
    QPainterPath path(start);
    path.lineTo(start.x(), bend);
    path.lineTo(r.center().x(), bend);
    path.lineTo(r.center().x(), r.top());
    p.drawPath(path);
    if (r.top() < bar.bottom()) L::arrowUp(p, QPointF(start.x(), (start.y() + bend) / 2));
  }
}

void GrafcetChartView::mousePressEvent(QMouseEvent* event) {
  const QPointF pos = toWidget().inverted().map(event->position());
  for (auto it = layout_.steps.cbegin(); it != layout_.steps.cend(); ++it)
    if (it.value().adjusted(-2, -2, 2, 2).contains(pos)) {
      emit stepClicked(it.key());
      return;
    }
  for (auto it = layout_.transitions.cbegin(); it != layout_.transitions.cend(); ++it)
    if (it.value().bar.adjusted(-4, -7, 4, 7).contains(pos)) {
      emit transitionClicked(it.key());
      return;
    }
  QWidget::mousePressEvent(event);
}

bool GrafcetChartView::event(QEvent* event) {
  if (event->type() != QEvent::ToolTip) return QWidget::event(event);
  const QPointF pos = static_cast<QHelpEvent*>(event)->pos();
  QString tip;
  for (const GrafcetStepView& s : chart_.steps)
    if (stepRect(s.id).adjusted(-2, -2, 2, 2).contains(pos))
      tip = tr("Step %1%2%3\nActions: %4%5")
                .arg(s.id)
                .arg(s.name.isEmpty() ? QString() : QStringLiteral(": ") + s.name)
                .arg(s.initial ? tr(" (initial)") : QString())
                .arg(s.actions.isEmpty() ? tr("none") : s.actions.join(QLatin1Char(' ')))
                .arg(active_.contains(s.id) ? tr("\nActive") : QString());
  for (const GrafcetTransitionView& t : chart_.transitions)
    if (transitionRect(t.id).adjusted(-4, -7, 4, 7).contains(pos)) {
      QStringList from, to;
      for (int f : t.from) from << QString::number(f);
      for (int s : t.to) to << QString::number(s);
      tip = tr("Transition (%1), priority %2: %3\nfrom step %4 to step %5")
                .arg(t.id)
                .arg(t.priority)
                .arg(t.receptivity, from.join(QStringLiteral(", ")), to.join(QStringLiteral(", ")));
    }
  if (tip.isEmpty())
    QToolTip::hideText();
  else
    QToolTip::showText(static_cast<QHelpEvent*>(event)->globalPos(), tip, this);
  return true;
}

bool GrafcetChartView::saveImage(const QString& path, int width, int height) {
  if (path.isEmpty() || width <= 0 || height <= 0) return false;
  QImage image(width, height, QImage::Format_ARGB32);
  image.fill(Qt::white);
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing, true);
  p.setRenderHint(QPainter::TextAntialiasing, true);
  const double scale = std::min({width / content_.width(), height / content_.height(), 2.0});
  p.translate((width - scale * content_.width()) / 2, (height - scale * content_.height()) / 2);
  p.scale(scale, scale);
  paintChart(p);
  p.end();
  return image.save(path, "PNG");
}

}  // namespace mx::widgets
