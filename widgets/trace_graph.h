#pragma once
// One time trace on a QCustomPlot, drawn as its raw samples while the shown time range holds at most
// two per pixel column of the axis rect, else as their min/max envelope (traceEnvelope): a light band
// between two edges in the trace's colour, so that a long dense oscillation reads as its extent and
// not as a solid block of zigzags. A bucket of the envelope is a pixel column, or the shortest bucket
// set when that is longer (a tooth period: each bucket then holds whole cuts and the edges follow the
// vibration's amplitude instead of its phase). One legend entry either way. show() redraws for the
// plot's current time range and width (SimulationView calls it at each layout of the plot).
#include <QColor>
#include <QString>
#include <span>
#include <utility>

class QCPAxis;
class QCPGraph;
class QCustomPlot;

namespace mx::widgets {

class TraceGraph {
 public:
  static constexpr int kRawSamplesPerColumn = 2;

  static constexpr int kBandAlpha = 45;

  TraceGraph(QCustomPlot* plot, QCPAxis* value_axis, const QColor& color, int band_alpha = kBandAlpha);

  void setName(const QString& name);
  void setShortestBucket(double seconds);  // <= 0: a pixel column
  // `time` ascending; both in plot units.
  void show(std::span<const double> time, std::span<const double> value);

  bool envelopeShown() const { return envelope_; }
  int drawnPoints() const;                       // raw samples, or both edges' points
  std::pair<double, double> drawnRange() const;  // least and greatest value drawn; (0, 0) when none
  int columns() const { return columns_; }       // pixel columns of the last show()
  int buckets() const { return buckets_; }       // envelope buckets of the last show()

 private:
  void useEnvelope(bool envelope);

  QCustomPlot* plot_;
  QCPGraph* raw_;    // the legend entry
  QCPGraph* lower_;  // carries the band: a channel fill up to upper_
  QCPGraph* upper_;
  QColor band_;
  bool envelope_ = false;
  double shortest_bucket_s_ = 0.0;
  int columns_ = 0;
  int buckets_ = 0;
};

}  // namespace mx::widgets
