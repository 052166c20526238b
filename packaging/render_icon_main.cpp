// millexpert-render-icon SVG SIZE OUT.png: the application icon rendered at SIZE x SIZE pixels for the
// hicolor icon theme (packaging/DesktopIntegration.cmake), with Qt Svg, which the programs link already.
// Exit codes: 0 ok, 1 the PNG cannot be written, 2 bad input.
#include <QDir>
#include <QFileInfo>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>
#include <QTextStream>

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");  // build step
  QGuiApplication app(argc, argv);
  const QStringList args = QGuiApplication::arguments();
  bool size_ok = false;
  const int size = args.value(2).toInt(&size_ok);
  if (args.size() != 4 || !size_ok || size < 8 || size > 1024) {
    QTextStream(stderr) << "usage: millexpert-render-icon SVG SIZE OUT.png (SIZE 8 to 1024)\n";
    return 2;
  }
  QSvgRenderer svg(args[1]);
  if (!svg.isValid()) {
    QTextStream(stderr) << "millexpert-render-icon: " << args[1] << ": not a readable SVG\n";
    return 2;
  }
  QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
  image.fill(Qt::transparent);
  QPainter painter(&image);
  painter.setRenderHints(QPainter::Antialiasing | QPainter::SmoothPixmapTransform);
  svg.render(&painter);
  painter.end();
  const QString out = args[3];
  if (!QDir().mkpath(QFileInfo(out).absolutePath()) || !image.save(out, "PNG")) {
    QTextStream(stderr) << "millexpert-render-icon: cannot write " << out << '\n';
    return 1;
  }
  return 0;
}
