// The glossary of the window's symbols (ROS, ΔN_s, q*, q**, η, J_c): each text is plain (no markup
// QWhatsThis would take for rich text), one to three sentences that start with the symbol and cite a
// source, and docs/user-guide.md's Glossary quotes each one word for word.
#include <QFile>
#include <QRegularExpression>
#include <QTextDocument>

#include "glossary.h"
#include "test_registry.h"

using namespace mx::widgets;

namespace {
int sentences(QString text) {
  for (const char* abbreviation : {"eq. ", "i.e. ", "e.g. "}) text.replace(abbreviation, "eq ");
  return int(text.count(QRegularExpression(R"(\.(\s|$))")));
}

// The guide as a reader sees it: Markdown escapes (q\*) rendered, line breaks as spaces.
QString renderedGuide() {
  QFile file(MX_PROJECTS_DIR "/../docs/user-guide.md");
  if (!file.open(QIODevice::ReadOnly)) return {};
  QTextDocument document;
  document.setMarkdown(QString::fromUtf8(file.readAll()));
  return document.toPlainText().simplified();
}
}  // namespace

class TestGlossary : public QObject {
  Q_OBJECT
 private slots:
  void everyTermHasAShortPlainTextWithItsSource() {
    QCOMPARE(kGlossaryTerms.size(), std::size_t(6));
    for (Term term : kGlossaryTerms) {
      const QString symbol = termSymbol(term), text = glossaryText(term);
      QVERIFY2(!symbol.isEmpty(), qPrintable(text));
      QVERIFY2(text.startsWith(symbol + " ") || text.startsWith(symbol + ":"), qPrintable(text));
      QVERIFY2(!text.contains('<'), qPrintable(text));
      const int n = sentences(text);
      QVERIFY2(n >= 1 && n <= 3, qPrintable(QString("%1 sentences: %2").arg(n).arg(text)));
      QVERIFY2(text.contains(QRegularExpression(R"(eq\. \d+)")), qPrintable(text));
    }
    QCOMPARE(termSymbol(Term::DeltaNs), QString("\u0394N_s"));
    QCOMPARE(termSymbol(Term::Eta), QString("\u03b7"));
  }

  void theUserGuideQuotesEveryText() {
    const QString guide = renderedGuide();
    QVERIFY2(guide.contains("Glossary"), "docs/user-guide.md was not read or has no Glossary");
    for (Term term : kGlossaryTerms)
      QVERIFY2(guide.contains(glossaryText(term).simplified()),
               qPrintable("docs/user-guide.md does not quote: " + glossaryText(term)));
  }
};

MX_REGISTER_TEST(TestGlossary)
#include "test_glossary.moc"
