// Settings > Learning database: the URL field's edge values give the message of the location rules
// (services/learning_location.h, the host's validator) prefixed by the field, and disable OK; a
// password never shows; the chosen location round-trips; Test connection emits the location, shows
// "Testing..." until the host's result arrives, and shows that result.
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSignalSpy>
#include <stdexcept>

#include "learning_database_dialog.h"
#include "services/learning_location.h"
#include "test_registry.h"

using mx::widgets::LearningDatabaseDialog;

namespace {

const QString kDefault = QStringLiteral("/srv/op/.local/share/MillExpert/learning.sqlite");

// The host's validator: what the GUI passes in (app/gui/pareto_feature_settings.cpp).
QString problemOf(const QString& location) {
  try {
    mx::app::parseLearningLocation(location);
    return {};
  } catch (const std::invalid_argument& e) {
    return QString::fromStdString(e.what());
  }
}

}  // namespace

class TestLearningDatabaseDialog : public QObject {
  Q_OBJECT
 private slots:
  void urlField_data() {
    QTest::addColumn<QString>("url");
    QTest::addColumn<QString>("problem");  // "" = valid
    const QString form = "postgresql://user@host:5432/learning";
    QTest::newRow("empty") << ""
                           << "PostgreSQL URL: empty; enter " + form;
    QTest::newRow("blank") << "   "
                           << "PostgreSQL URL: empty; enter " + form;
    QTest::newRow("other scheme") << "mysql://u@h/db"
                                  << "PostgreSQL URL 'mysql://u@h/db': must start with postgresql:// (" + form + ")";
    QTest::newRow("a file") << "/srv/learning.sqlite"
                            << "PostgreSQL URL '/srv/learning.sqlite': must start with postgresql:// (" + form + ")";
    QTest::newRow("user, host, db") << "postgresql://u@h/learning"
                                    << "";
    QTest::newRow("postgres scheme, no user") << "postgres://h/learning"
                                              << "";
    QTest::newRow("upper-case scheme") << "POSTGRESQL://h/learning"
                                       << "";
    QTest::newRow("port 1") << "postgresql://u@h:1/x"
                            << "";
    QTest::newRow("port 65535") << "postgresql://u@h:65535/x"
                                << "";
    QTest::newRow("port 0") << "postgresql://u@h:0/x"
                            << "PostgreSQL URL: learning database 'postgresql://u@h:0/x': port 0 is outside 1..65535";
    QTest::newRow("port 65536") << "postgresql://u@h:65536/x"
                                << "PostgreSQL URL: learning database 'postgresql://u@h:65536/x': not a valid URL "
                                   "(postgresql://[user@]host[:port]/database[?options])";
    QTest::newRow("invalid, password quoted nowhere")
        << "postgresql://u:sec ret@h:99999/x"
        << "PostgreSQL URL: learning database 'postgresql://u:***@h:99999/x': not a valid URL "
           "(postgresql://[user@]host[:port]/database[?options])";
    QTest::newRow("options") << "postgresql://u@h/x?sslmode=require&connect_timeout=5"
                             << "";
    QTest::newRow("timeout 3600 s") << "postgresql://u@h/x?connect_timeout=3600"
                                    << "";
    QTest::newRow("timeout 0 s") << "postgresql://u@h/x?connect_timeout=0"
                                 << "PostgreSQL URL: learning database 'postgresql://u@h/x?connect_timeout=0': "
                                    "connect_timeout = '0' is outside 1..3600 s";
    QTest::newRow("timeout 3601 s") << "postgresql://u@h/x?connect_timeout=3601"
                                    << "PostgreSQL URL: learning database 'postgresql://u@h/x?connect_timeout=3601': "
                                       "connect_timeout = '3601' is outside 1..3600 s";
    QTest::newRow("unknown option")
        << "postgresql://u@h/x?foo=1"
        << "PostgreSQL URL: learning database 'postgresql://u@h/x?foo=1': unknown option 'foo' (allowed: sslmode, "
           "sslrootcert, sslcert, sslkey, connect_timeout, target_session_attrs)";
    QTest::newRow("no host") << "postgresql://u@/x"
                             << "PostgreSQL URL: learning database 'postgresql://u@/x': no host "
                                "(postgresql://user@host[:port]/database)";
    QTest::newRow("no database") << "postgresql://u@h"
                                 << "PostgreSQL URL: learning database 'postgresql://u@h': no database name "
                                    "(postgresql://user@host[:port]/database)";
    QTest::newRow("password in the URL")
        << "postgresql://u:secret@h/x"
        << "PostgreSQL URL: learning database 'postgresql://u:***@h/x': a password is not accepted in the URL; "
           "give it in PGPASSWORD or ~/.pgpass";
    QTest::newRow("password option")
        << "postgresql://u@h/x?password=secret"
        << "PostgreSQL URL: learning database 'postgresql://u@h/x?password=***': a password is not accepted in the "
           "URL; give it in PGPASSWORD or ~/.pgpass";
  }
  void urlField() {
    QFETCH(QString, url);
    QFETCH(QString, problem);
    LearningDatabaseDialog dialog(kDefault, problemOf);
    dialog.serverChoice()->click();
    dialog.urlEdit()->setText(url);
    QCOMPARE(dialog.problem(), problem);
    QCOMPARE(dialog.problemLabel()->text(), problem);
    QCOMPARE(dialog.okButton()->isEnabled(), problem.isEmpty());
    QCOMPARE(dialog.testButton()->isEnabled(), problem.isEmpty());
    QVERIFY(!dialog.problem().contains("secret"));
    QVERIFY(!dialog.problem().contains("sec ret"));
    if (problem.isEmpty()) QCOMPARE(dialog.location(), url.trimmed());
  }

  void fileField_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("location");
    QTest::addColumn<QString>("problem");
    QTest::newRow("empty: the default file") << "" << kDefault << "";
    QTest::newRow("a path") << "/data/shop/learning.sqlite"
                            << "/data/shop/learning.sqlite"
                            << "";
    QTest::newRow("a path, padded") << "  /data/l.db "
                                    << "/data/l.db"
                                    << "";
    QTest::newRow("a URL in the file field")
        << "postgresql://u@h/x"
        << "postgresql://u@h/x"
        << "SQLite file 'postgresql://u@h/x': this is a server URL; choose \"PostgreSQL server\"";
  }
  void fileField() {
    QFETCH(QString, file);
    QFETCH(QString, location);
    QFETCH(QString, problem);
    LearningDatabaseDialog dialog(kDefault, problemOf);
    QVERIFY(dialog.fileChoice()->isChecked());
    dialog.fileEdit()->setText(file);
    QCOMPARE(dialog.problem(), problem);
    QCOMPARE(dialog.okButton()->isEnabled(), problem.isEmpty());
    QCOMPARE(dialog.location(), location);
    QVERIFY(dialog.fileEdit()->placeholderText().contains(kDefault));
  }

  // OK follows the chosen field only: an invalid URL does not block a valid file, and back.
  void okFollowsTheChosenField() {
    LearningDatabaseDialog dialog(kDefault, problemOf);
    dialog.urlEdit()->setText("postgresql://u@h:0/x");
    QVERIFY(dialog.okButton()->isEnabled());  // the file is chosen
    QVERIFY(!dialog.urlEdit()->isEnabled());
    dialog.serverChoice()->click();
    QVERIFY(!dialog.okButton()->isEnabled());
    QVERIFY(!dialog.fileEdit()->isEnabled());
    QVERIFY(!dialog.browseButton()->isEnabled());
    dialog.urlEdit()->setText("postgresql://u@h:5433/x");
    QVERIFY(dialog.okButton()->isEnabled());
    QCOMPARE(dialog.location(), QString("postgresql://u@h:5433/x"));
    dialog.fileChoice()->click();
    QCOMPARE(dialog.location(), kDefault);
  }

  void locationRoundTrips_data() {
    QTest::addColumn<QString>("location");
    QTest::addColumn<bool>("server");
    QTest::addColumn<QString>("fileText");
    QTest::newRow("default file") << kDefault << false << "";
    QTest::newRow("empty: default file") << "" << false << "";
    QTest::newRow("another file") << "/srv/learning.sqlite" << false << "/srv/learning.sqlite";
    QTest::newRow("URL") << "postgresql://planner@db.shop:5433/learning?sslmode=require" << true << "";
  }
  void locationRoundTrips() {
    QFETCH(QString, location);
    QFETCH(bool, server);
    QFETCH(QString, fileText);
    LearningDatabaseDialog dialog(kDefault, problemOf);
    dialog.setLocation(location);
    QCOMPARE(dialog.usesServer(), server);
    QCOMPARE(dialog.serverChoice()->isChecked(), server);
    QCOMPARE(dialog.fileEdit()->text(), fileText);
    QCOMPARE(dialog.location(), location.isEmpty() ? kDefault : location);
    QVERIFY(dialog.okButton()->isEnabled());
    // A second dialog given what the first chose shows the same choice.
    LearningDatabaseDialog again(kDefault, problemOf);
    again.setLocation(dialog.location());
    QCOMPARE(again.location(), dialog.location());
    QCOMPARE(again.usesServer(), server);
  }

  void testConnectionAsksTheHost() {
    LearningDatabaseDialog dialog(kDefault, problemOf);
    QSignalSpy requested(&dialog, &LearningDatabaseDialog::testRequested);
    dialog.setLocation("postgresql://u@db.shop/learning?connect_timeout=3");
    dialog.testButton()->click();
    QCOMPARE(requested.count(), 1);
    QCOMPARE(requested.at(0).at(0).toString(), QString("postgresql://u@db.shop/learning?connect_timeout=3"));
    QCOMPARE(dialog.testButton()->text(), QString("Testing..."));
    QVERIFY(!dialog.testButton()->isEnabled());
    QVERIFY(dialog.okButton()->isEnabled());  // the dialog stays usable while the host tests
    dialog.showTestResult(true, "Connected to postgresql://u@db.shop:5432/learning: schema 2, 1 234 records");
    QCOMPARE(dialog.resultLabel()->text(),
             QString("Connected to postgresql://u@db.shop:5432/learning: schema 2, 1 234 records"));
    QCOMPARE(dialog.testButton()->text(), QString("Test connection"));
    QVERIFY(dialog.testButton()->isEnabled());
    dialog.testButton()->click();
    dialog.showTestResult(false, "learning database 'postgresql://u@db.shop:5432/learning': cannot connect");
    QCOMPARE(dialog.resultLabel()->text(),
             QString("learning database 'postgresql://u@db.shop:5432/learning': cannot connect"));
    QCOMPARE(requested.count(), 2);
    // Another location: the old result is not its result.
    dialog.urlEdit()->setText("postgresql://u@other/learning");
    QVERIFY(dialog.resultLabel()->text().isEmpty());
  }

  void fileTestCarriesTheDefaultFile() {
    LearningDatabaseDialog dialog(kDefault, problemOf);
    QSignalSpy requested(&dialog, &LearningDatabaseDialog::testRequested);
    dialog.testButton()->click();
    QCOMPARE(requested.count(), 1);
    QCOMPARE(requested.at(0).at(0).toString(), kDefault);
  }

  void labelsAndPasswordNote() {
    LearningDatabaseDialog dialog(kDefault, problemOf);
    QCOMPARE(dialog.windowTitle(), QString("Learning database"));
    QCOMPARE(dialog.urlEdit()->placeholderText(), QString("postgresql://user@host:5432/learning"));
    auto* note = dialog.findChild<QLabel*>("learning_password_note");
    QVERIFY(note);
    QVERIFY(note->text().contains("PGPASSWORD"));
    QVERIFY(note->text().contains("~/.pgpass"));
    QVERIFY(note->text().contains("never stored"));
    for (QWidget* w : std::initializer_list<QWidget*>{dialog.fileChoice(), dialog.serverChoice(), dialog.fileEdit(),
                                                      dialog.urlEdit(), dialog.browseButton(), dialog.testButton()})
      QVERIFY2(!w->toolTip().isEmpty(), qPrintable(w->objectName()));
  }
};

MX_REGISTER_TEST(TestLearningDatabaseDialog)
#include "test_learning_database_dialog.moc"
