#pragma once
// Writes the expert report (ReportBuilder) to files:
//   HTML  UTF-8; the figures copied into a sibling folder "<name>_files/" (relative links), or
//         embedded as data: URIs (a single self-contained file);
//   PDF   QTextDocument laid out on an A4 QPrinter (HighResolution, PdfFormat, 15 mm margins),
//         painted page by page with a footer line (MillExpert version, date, page i/n).
// Every write throws std::runtime_error naming the file when it cannot be written.
#include <QString>

#include "report_data.h"
#include "shop_units.h"

namespace mx::gui {

enum class HtmlImages { SiblingFolder, Embedded };

class ReportWriter {
 public:
  explicit ReportWriter(const ReportData& data, const widgets::ShopUnits& units = widgets::ShopUnits::metric())
      : data_(data), units_(units) {}

  void writeHtml(const QString& path, HtmlImages images = HtmlImages::SiblingFolder) const;
  void writePdf(const QString& path) const;

  // The folder that writeHtml(path, SiblingFolder) fills: "<dir>/<base name>_files".
  static QString imageFolder(const QString& html_path);

 private:
  const ReportData& data_;
  widgets::ShopUnits units_;
};

}  // namespace mx::gui
