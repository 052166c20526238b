#pragma once
// Stability-lobe chart: one envelope per tool (nominal and margined), spindle speed [rpm] against
// axial depth [mm]. The plot library (QCustomPlot) stays behind this class.
#include <QColor>
#include <QString>
#include <QVector>
#include <QWidget>

class QCustomPlot;

namespace mx::widgets {

struct ToolLobeSeries {
  QString tool_id;
  QVector<double> speed_rpm;
  QVector<double> nominal_mm;   // delta = 0, alpha = 1; NaN where none below the cap
  QVector<double> margined_mm;  // alpha * delta-lobes (Rule 1); NaN where none below the cap
};

class LobeChartView : public QWidget {
  Q_OBJECT
 public:
  explicit LobeChartView(QWidget* parent = nullptr);

  void setSeries(const QVector<ToolLobeSeries>& series, double delta_per_s, double alpha);
  void clear();
  bool saveImage(const QString& path, int width = 0, int height = 0);
  static QColor toolColor(int index);

 signals:
  // A point on the chart was clicked (speed [rpm], depth [mm]).
  void operatingPointPicked(double speed_rpm, double depth_mm);

 private:
  QCustomPlot* plot_;
};

}  // namespace mx::widgets
