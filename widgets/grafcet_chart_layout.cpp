#include "grafcet_chart_layout.h"

#include <QFontMetricsF>
#include <QObject>
#include <QPainter>
#include <QPainterPath>
#include <QPicture>
#include <algorithm>
#include <queue>

namespace mx::widgets {

namespace {
QString transitionLabel(int id) {
  return QStringLiteral("(%1)").arg(id);
}
}  // namespace

QFont GrafcetLayout::font(QFont base, double point_size, bool bold, bool italic) {
  base.setPointSizeF(point_size);
  base.setBold(bold);
  base.setItalic(italic);
  return base;
}

void GrafcetLayout::arrowUp(QPainter& p, QPointF tip) {
  QPainterPath head;
  head.moveTo(tip);
  head.lineTo(tip + QPointF(-5, 9));
  head.lineTo(tip + QPointF(5, 9));
  head.closeSubpath();
  p.fillPath(head, p.pen().color());
}

GrafcetLayout GrafcetLayout::compute(const GrafcetChartData& chart_, const QFont& base) {
  GrafcetLayout L;
  auto& steps_ = L.steps;
  auto& transitions_ = L.transitions;
  const QFontMetricsF name_fm(font(base, kNamePt, false, true)), text_fm(font(base, kTextPt));
  const QFontMetricsF action_fm(font(base, kActionPt, true));
  QHash<int, int> order, depth;  // step id -> chart order / BFS level
  for (int i = 0; i < chart_.steps.size(); ++i) order.insert(chart_.steps[i].id, i);
  QHash<int, QVector<int>> out;  // step id -> transitions (indices) leaving it
  for (int i = 0; i < chart_.transitions.size(); ++i)
    for (int f : chart_.transitions[i].from)
      if (order.contains(f) && !out[f].contains(i)) out[f].push_back(i);

  // Levels: BFS from the initial steps, then from any step not reached yet.
  auto bfs = [&](const QList<int>& roots) {
    std::queue<int> q;
    for (int r : roots) {
      depth.insert(r, 0);
      q.push(r);
    }
    while (!q.empty()) {
      const int s = q.front();
      q.pop();
      for (int ti : out.value(s))
        for (int to : chart_.transitions[ti].to)
          if (order.contains(to) && !depth.contains(to)) {
            depth.insert(to, depth[s] + 1);
            q.push(to);
          }
    }
  };
  QList<int> roots;
  for (const GrafcetStepView& s : chart_.steps)
    if (s.initial && !roots.contains(s.id)) roots << s.id;
  if (!roots.isEmpty()) bfs(roots);
  for (const GrafcetStepView& s : chart_.steps)
    if (!depth.contains(s.id)) bfs({s.id});
  int max_depth = 0;
  for (int d : std::as_const(depth)) max_depth = std::max(max_depth, d);

  // Owner of a transition: its deepest source step. Back: a target not below the owner.
  QVector<int> owner(chart_.transitions.size(), -1);
  QVector<bool> back(chart_.transitions.size(), false);
  for (int i = 0; i < chart_.transitions.size(); ++i) {
    for (int f : chart_.transitions[i].from)
      if (order.contains(f) && (owner[i] < 0 || depth[f] > depth[owner[i]])) owner[i] = f;
    if (owner[i] < 0) continue;
    for (int to : chart_.transitions[i].to)
      if (order.contains(to) && depth[to] <= depth[owner[i]]) back[i] = true;
  }
  for (auto& list : out) {  // transitions under a step: the designer's priority order, left first
    list.erase(std::remove_if(list.begin(), list.end(), [&](int ti) { return owner[ti] < 0; }), list.end());
    std::stable_sort(list.begin(), list.end(), [&](int a, int b) {
      const auto &ta = chart_.transitions[a], &tb = chart_.transitions[b];
      return std::pair(ta.priority, ta.id) < std::pair(tb.priority, tb.id);
    });
  }
  for (auto it = out.begin(); it != out.end(); ++it) {
    QVector<int> mine;
    for (int ti : it.value())
      if (owner[ti] == it.key()) mine << ti;
    it.value() = mine;
  }

  // Columns, level by level: a step under the slot of the transition that reaches it first.
  QHash<int, int> step_col;
  QVector<int> slot_col(chart_.transitions.size(), -1);
  int max_col = 0;
  for (int level = 0; level <= max_depth; ++level) {
    QVector<std::pair<int, int>> row;  // (desired column, step id)
    for (const GrafcetStepView& s : chart_.steps) {
      if (depth.value(s.id) != level || steps_.contains(s.id) || step_col.contains(s.id)) continue;
      int desired = level == 0 ? 0 : 1 << 20;
      for (int i = 0; i < chart_.transitions.size(); ++i) {
        const int k = static_cast<int>(chart_.transitions[i].to.indexOf(s.id));
        if (k >= 0 && !back[i] && slot_col[i] >= 0) desired = std::min(desired, slot_col[i] + k);
      }
      row.push_back({desired == 1 << 20 ? 0 : desired, s.id});
    }
    std::stable_sort(row.begin(), row.end(), [&](const auto& a, const auto& b) {
      return std::pair(a.first, order[a.second]) < std::pair(b.first, order[b.second]);
    });
    int next_free = 0;
    for (const auto& [desired, id] : row) {
      const int col = std::max(desired, next_free);
      step_col.insert(id, col);
      const QVector<int> mine = out.value(id);
      for (int j = 0; j < mine.size(); ++j) slot_col[mine[j]] = col + j;
      next_free = col + std::max<int>(1, static_cast<int>(mine.size()));
      max_col = std::max(max_col, next_free - 1);
    }
  }
  const int free_col = max_col + 1;  // transitions without a source step
  bool any_free = false;

  // Column widths from the texts of the steps and transitions in each column.
  const int n_cols = free_col + 1;
  QVector<double> left(n_cols, kStepW / 2 + 8), right(n_cols, kStepW / 2 + 8);
  for (const GrafcetStepView& s : chart_.steps) {
    const int c = step_col.value(s.id);
    left[c] = std::max(left[c], std::min(kNameMaxW, name_fm.horizontalAdvance(s.name)) + 8 + kStepW / 2);
    double actions = 0;
    for (const QString& a : s.actions) actions += std::max(26.0, action_fm.horizontalAdvance(a) + 12);
    right[c] = std::max(right[c], kStepW / 2 + 16 + actions);
  }
  for (int i = 0; i < chart_.transitions.size(); ++i) {
    const GrafcetTransitionView& t = chart_.transitions[i];
    const int c = slot_col[i] >= 0 ? slot_col[i] : free_col;
    left[c] = std::max(left[c], text_fm.horizontalAdvance(transitionLabel(t.id)) + 8 + kBarW / 2);
    right[c] = std::max(right[c], kBarW / 2 + 8 + std::min(kReceptivityMaxW, text_fm.horizontalAdvance(t.receptivity)));
  }

  // Back-arc lanes: the highest departure nearest the chart.
  QVector<int> backs;
  for (int i = 0; i < chart_.transitions.size(); ++i)
    if (back[i]) backs << i;
  const double lanes_w = backs.isEmpty() ? 0 : backs.size() * kLaneGap + 6;
  QVector<double> xs(n_cols);  // column centres
  xs[0] = kMargin + lanes_w + left[0];
  for (int c = 1; c < n_cols; ++c) xs[c] = xs[c - 1] + right[c - 1] + 28 + left[c];
  const double top0 = kMargin + kHeaderH;
  L.lanes_left = xs[0] - left[0] - 6;
  for (auto it = step_col.cbegin(); it != step_col.cend(); ++it) {
    const double cx = xs[it.value()], top = top0 + depth[it.key()] * kLevelH;
    steps_.insert(it.key(), QRectF(cx - kStepW / 2, top, kStepW, kStepH));
  }
  for (int i = 0; i < chart_.transitions.size(); ++i) {
    const GrafcetTransitionView& t = chart_.transitions[i];
    Transition g;
    g.back = back[i];
    double cx = 0, y = 0;
    if (owner[i] >= 0) {
      cx = xs[slot_col[i]];
      y = steps_[owner[i]].bottom() + kBarBelowStep;
    } else {  // no source: in a free column, above its first target
      any_free = true;
      int level = 0;
      for (int to : t.to)
        if (depth.contains(to)) level = std::max(0, depth[to] - 1);
      cx = xs[free_col];
      y = top0 + level * kLevelH + kStepH + kBarBelowStep;
    }
    g.bar = QRectF(cx - kBarW / 2, y, kBarW, kBarH);
    transitions_.insert(t.id, g);
  }
  // Departures under the bar (several back arcs of one step at distinct heights), then lanes.
  QHash<int, int> backs_of_owner;
  for (int i : std::as_const(backs)) {
    Transition& g = transitions_[chart_.transitions[i].id];
    g.depart_y = g.bar.bottom() + 10 + 7 * std::min(3, backs_of_owner[owner[i]]++);
  }
  std::stable_sort(backs.begin(), backs.end(), [&](int a, int b) {
    return transitions_[chart_.transitions[a].id].depart_y < transitions_[chart_.transitions[b].id].depart_y;
  });
  for (int lane = 0; lane < backs.size(); ++lane) transitions_[chart_.transitions[backs[lane]].id].lane = lane;

  const int last = any_free ? free_col : max_col;
  QPicture legend;  // measured by drawing it
  QPainter measure(&legend);
  const double legend_w = paintHeader(measure, base, QString()) + kMargin;
  const double width = std::max(xs[last] + right[last] + kMargin, legend_w);
  L.content = QSizeF(std::max(width, 760.0), top0 + (max_depth + 1) * kLevelH + kMargin);
  return L;
}

double GrafcetLayout::paintHeader(QPainter& p, const QFont& base, const QString& title) {
  const QColor kInk = ink(), kActiveFill = activeFill(), kToken = token(), kBackArc = backArc();
  p.setPen(kInk);
  p.setFont(font(base, kTitlePt, true));
  p.drawText(QRectF(kMargin, kMargin - 6, 1000, 22), Qt::AlignLeft | Qt::AlignVCenter, title);
  const QFont f = font(base, kLegendPt);
  const QFontMetricsF fm(f);
  p.setFont(f);
  double x = kMargin;
  const double y = kMargin + 26, h = 18;
  auto label = [&](const QString& text) {
    p.setPen(kInk);
    p.drawText(QRectF(x, y, fm.horizontalAdvance(text) + 4, h), Qt::AlignLeft | Qt::AlignVCenter, text);
    x += fm.horizontalAdvance(text) + 18;
  };
  p.setPen(QPen(kInk, 1.2));
  p.setBrush(Qt::NoBrush);
  p.drawRect(QRectF(x, y, h, h));
  p.drawRect(QRectF(x + 3, y + 3, h - 6, h - 6));
  x += h + 5;
  label(QObject::tr("initial step"));
  p.setBrush(kActiveFill);
  p.drawRect(QRectF(x, y, h, h));
  p.setPen(Qt::NoPen);
  p.setBrush(kToken);
  p.drawEllipse(QPointF(x + h / 2, y + h / 2), 4, 4);
  x += h + 5;
  label(QObject::tr("active step (token)"));
  p.fillRect(QRectF(x, y + h / 2 - 3, 24, 6), kInk);
  x += 29;
  label(QObject::tr("(n) transition, receptivity on the right"));
  p.setPen(QPen(kInk, 1.2));
  p.setBrush(Qt::white);
  p.drawRect(QRectF(x, y, 22, h));
  p.drawText(QRectF(x, y, 22, h), Qt::AlignCenter, QStringLiteral("A"));
  x += 27;
  label(QObject::tr("level action"));
  p.drawRect(QRectF(x, y, 26, h));
  p.drawText(QRectF(x, y, 26, h), Qt::AlignCenter, QStringLiteral("L*"));
  x += 31;
  label(QObject::tr("impulse action"));
  p.setPen(QPen(kBackArc, 1.4));
  p.drawLine(QPointF(x + 5, y + h), QPointF(x + 5, y + 1));
  arrowUp(p, QPointF(x + 5, y));
  x += 14;
  label(QObject::tr("back arc (upward)"));
  return x - 18;
}

}  // namespace mx::widgets
