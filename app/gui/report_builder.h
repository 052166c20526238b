#pragma once
// The expert report as HTML, built from ReportData: numbered sections, numbered tables with captions
// and units in the column heads, numbered figures with captions, and a footer line (MillExpert version
// and date). Two flavours of the same content:
//   Browser   tables carry a <caption> (for the .html file);
//   RichText  QTextDocument has no <caption>: each caption is a paragraph right above its table (PDF).
// Image sources are supplied by the caller (relative file, data: URI or resource name). Lengths, chip
// loads, feed rates, power and MRR are written in the given shop units (the GUI's; metric by default).
#include <QString>
#include <QStringList>
#include <functional>

#include "report_data.h"
#include "shop_units.h"

namespace mx::gui {

enum class ReportFlavour { Browser, RichText };

class ReportBuilder {
 public:
  using ImageSource = std::function<QString(const QString& image_path)>;

  ReportBuilder(const ReportData& data, ReportFlavour flavour, ImageSource source,
                const widgets::ShopUnits& units = widgets::ShopUnits::metric());

  QString html() const;    // a complete document
  QString footer() const;  // "MillExpert <version> · generated <date> · <project file>"

  // Number formats of the report (C locale; "—" for non-finite values). The test compares against them.
  static QString formatCost(double cost);  // 4 decimals
  static QString formatNumber(double value, int decimals);

 private:
  QString table(const QString& caption, const QStringList& head, const QList<QStringList>& rows) const;
  QString figure(const QString& image, const QString& caption) const;
  QString projectSection() const;
  QString rankingSection() const;
  QString selectionSection() const;
  QString figureSection() const;
  // A value (SI: m, W, m³/s) as shown in the report's units, and a unit's symbol (HTML-escaped).
  QString length(double m) const;
  QString chipLoad(double m) const;
  QString power(double w) const;
  QString mrr(double m3_per_s) const;
  QString unit(widgets::Quantity q) const;

  const ReportData& d_;
  ReportFlavour flavour_;
  ImageSource source_;
  widgets::ShopUnits u_;
  mutable int tables_ = 0;
  mutable int figures_ = 0;
};

}  // namespace mx::gui
