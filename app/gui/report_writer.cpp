#include "report_writer.h"

#include <QAbstractTextDocumentLayout>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPrinter>
#include <QSaveFile>
#include <QTextDocument>
#include <QUrl>
#include <stdexcept>

#include "document/output_file.h"
#include "report_builder.h"

namespace mx::gui {

namespace {

[[noreturn]] void fail(const QString& what) {
  throw std::runtime_error(what.toStdString());
}

QByteArray readFile(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) fail(QString("cannot read the figure '%1'").arg(path));
  return file.readAll();
}

constexpr double kMarginMm = 15.0;

}  // namespace

QString ReportWriter::imageFolder(const QString& html_path) {
  const QFileInfo info(html_path);
  return info.dir().filePath(info.completeBaseName() + "_files");
}

void ReportWriter::writeHtml(const QString& path, HtmlImages images) const {
  if (const QString problem = app::outputFileProblem(path); !problem.isEmpty())
    fail(QString("cannot write '%1': %2").arg(path, problem));
  const QString folder = imageFolder(path);
  const QString folder_name = QFileInfo(folder).fileName();
  if (images == HtmlImages::SiblingFolder && !QDir().mkpath(folder))
    fail(QString("cannot create the folder '%1'").arg(folder));
  const ReportBuilder builder(
      data_, ReportFlavour::Browser,
      [&](const QString& image) -> QString {
        if (images == HtmlImages::Embedded)
          return "data:image/png;base64," + QString::fromLatin1(readFile(image).toBase64());
        const QString name = QFileInfo(image).fileName();
        const QString target = QDir(folder).filePath(name);
        if (QFileInfo(image).absoluteFilePath() != QFileInfo(target).absoluteFilePath()) {
          QFile::remove(target);
          if (!QFile::copy(image, target)) fail(QString("cannot copy the figure '%1' to '%2'").arg(image, target));
        }
        return folder_name + "/" + name;
      },
      units_);
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly)) fail(QString("cannot write '%1': %2").arg(path, file.errorString()));
  file.write(builder.html().toUtf8());
  if (!file.commit()) fail(QString("cannot write '%1': %2").arg(path, file.errorString()));
}

void ReportWriter::writePdf(const QString& path) const {
  if (const QString problem = app::outputFileProblem(path); !problem.isEmpty())
    fail(QString("cannot write '%1': %2").arg(path, problem));
  QPrinter printer(QPrinter::HighResolution);
  printer.setOutputFormat(QPrinter::PdfFormat);
  printer.setOutputFileName(path);
  printer.setPageSize(QPageSize(QPageSize::A4));
  printer.setPageOrientation(QPageLayout::Portrait);
  printer.setPageMargins(QMarginsF(kMarginMm, kMarginMm, kMarginMm, kMarginMm), QPageLayout::Millimeter);
  printer.setCreator("MillExpert " + data_.version);
  printer.setDocName("MillExpert report: " + data_.project.name);

  QTextDocument doc;
  doc.setDefaultFont(QFont("DejaVu Sans", 9));
  doc.documentLayout()->setPaintDevice(&printer);
  const ReportBuilder builder(
      data_, ReportFlavour::RichText,
      [&](const QString& image) -> QString {
        QString name = "mx-report://" + QFileInfo(image).fileName();
        QImage picture;
        if (!picture.loadFromData(readFile(image), "PNG"))
          fail(QString("the figure '%1' is not a PNG image").arg(image));
        doc.addResource(QTextDocument::ImageResource, QUrl(name), picture);
        return name;
      },
      units_);
  doc.setHtml(builder.html());

  const QRectF page = printer.pageLayout().paintRectPixels(printer.resolution());
  const QFont footer_font("DejaVu Sans", 7);
  const QFontMetricsF metrics(footer_font, &printer);
  const double footer_height = 2.5 * metrics.height();
  const double body_height = page.height() - footer_height;
  doc.setPageSize(QSizeF(page.width(), body_height));

  QPainter painter;
  if (!painter.begin(&printer)) fail(QString("cannot write '%1'").arg(path));
  const int pages = doc.pageCount();
  const QString footer = metrics.elidedText(builder.footer(), Qt::ElideMiddle, 0.85 * page.width());
  for (int i = 0; i < pages; ++i) {
    if (i > 0 && !printer.newPage()) fail(QString("cannot write '%1'").arg(path));
    painter.save();
    painter.translate(0.0, -i * body_height);
    doc.drawContents(&painter, QRectF(0.0, i * body_height, page.width(), body_height));
    painter.restore();
    painter.setFont(footer_font);
    painter.setPen(QPen(QColor(120, 120, 120), 0.0));
    painter.drawLine(QPointF(0.0, page.height() - 1.6 * metrics.height()),
                     QPointF(page.width(), page.height() - 1.6 * metrics.height()));
    painter.setPen(QColor(70, 70, 70));
    const QRectF footer_rect(0.0, page.height() - 1.3 * metrics.height(), page.width(), 1.3 * metrics.height());
    painter.drawText(footer_rect, Qt::AlignLeft | Qt::AlignBottom, footer);
    painter.drawText(footer_rect, Qt::AlignRight | Qt::AlignBottom, QString("page %1 / %2").arg(i + 1).arg(pages));
  }
  if (!painter.end()) fail(QString("cannot write '%1'").arg(path));
}

}  // namespace mx::gui
