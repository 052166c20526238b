// Where the learning database lives (app/services/learning_location.h): a path or a postgresql:// URL,
// its parts, the connect options libpq gets, and every refused form with the reason named; the user's
// setting (learning/database) round-trips.
#include <QSettings>
#include <stdexcept>

#include "services/learning_location.h"
#include "test_registry.h"

using mx::app::LearningBackend;
using mx::app::LearningLocation;
using mx::app::parseLearningLocation;

class TestLearningLocation : public QObject {
  Q_OBJECT

 private slots:
  void accepted_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<bool>("postgres");
    QTest::addColumn<QString>("user");
    QTest::addColumn<QString>("host");
    QTest::addColumn<int>("port");
    QTest::addColumn<QString>("database");
    QTest::addColumn<QString>("options");
    QTest::addColumn<QString>("display");
    QTest::newRow("file") << "shop/learning.sqlite" << false << ""
                          << "" << 5432 << ""
                          << ""
                          << "shop/learning.sqlite";
    QTest::newRow("full url") << "postgresql://planner@db.shop.local:6543/learning" << true << "planner"
                              << "db.shop.local" << 6543 << "learning"
                              << "connect_timeout=10"
                              << "postgresql://planner@db.shop.local:6543/learning";
    QTest::newRow("default port and user") << "postgres://db/learning" << true << ""
                                           << "db" << 5432 << "learning"
                                           << "connect_timeout=10"
                                           << "postgresql://db:5432/learning";
    QTest::newRow("ipv6") << "postgresql://u@[::1]:5433/l" << true << "u"
                          << "::1" << 5433 << "l"
                          << "connect_timeout=10"
                          << "postgresql://u@[::1]:5433/l";
    QTest::newRow("options") << "postgresql://u@h/l?sslmode=require&connect_timeout=3" << true << "u"
                             << "h" << 5432 << "l"
                             << "sslmode=require;connect_timeout=3"
                             << "postgresql://u@h:5432/l";
    QTest::newRow("path with a space") << "postgresql://u@h/l?sslrootcert=/shop/Jane%20Doe/ca.crt" << true << "u"
                                       << "h" << 5432 << "l"
                                       << "sslrootcert='/shop/Jane Doe/ca.crt';connect_timeout=10"
                                       << "postgresql://u@h:5432/l";
    QTest::newRow("quote and backslash") << R"(postgresql://u@h/l?sslkey=/k/it's%5Cx)" << true << "u"
                                         << "h" << 5432 << "l"
                                         << R"(sslkey='/k/it\'s\\x';connect_timeout=10)"
                                         << "postgresql://u@h:5432/l";
    QTest::newRow("timeout 1 s") << "postgresql://u@h/l?connect_timeout=1" << true << "u"
                                 << "h" << 5432 << "l"
                                 << "connect_timeout=1"
                                 << "postgresql://u@h:5432/l";
    QTest::newRow("timeout 3600 s") << "postgresql://u@h/l?connect_timeout=3600" << true << "u"
                                    << "h" << 5432 << "l"
                                    << "connect_timeout=3600"
                                    << "postgresql://u@h:5432/l";
    QTest::newRow("port 65535") << "postgresql://u@h:65535/l" << true << "u"
                                << "h" << 65535 << "l"
                                << "connect_timeout=10"
                                << "postgresql://u@h:65535/l";
  }

  void accepted() {
    QFETCH(QString, text);
    QFETCH(bool, postgres);
    const LearningLocation l = parseLearningLocation(text);
    QCOMPARE(l.backend == LearningBackend::PostgreSql, postgres);
    QTEST(l.user, "user");
    QTEST(l.host, "host");
    QTEST(l.port, "port");
    QTEST(l.database, "database");
    QTEST(l.connect_options, "options");
    QTEST(l.display(), "display");
    if (!postgres) QCOMPARE(l.file, text);
  }

  void refused_data() {
    QTest::addColumn<QString>("text");
    QTest::addColumn<QString>("reason");
    QTest::newRow("empty") << ""
                           << "no file name or URL given";
    QTest::newRow("blank") << "   "
                           << "no file name or URL given";
    QTest::newRow("password") << "postgresql://shop:secret@h/l"
                              << "a password is not accepted";
    QTest::newRow("password option") << "postgresql://u@h/l?password=secret"
                                     << "a password is not accepted";
    QTest::newRow("no host") << "postgresql:///learning"
                             << "no host";
    QTest::newRow("no database") << "postgresql://u@h"
                                 << "no database name";
    QTest::newRow("empty database") << "postgresql://u@h:5432/"
                                    << "no database name";
    QTest::newRow("nested path") << "postgresql://u@h/a/b"
                                 << "no database name";
    QTest::newRow("port 0") << "postgresql://u@h:0/l"
                            << "port 0 is outside 1..65535";
    QTest::newRow("port 65536") << "postgresql://u@h:65536/l"
                                << "not a valid URL";
    QTest::newRow("unknown option") << "postgresql://u@h/l?options=-c"
                                    << "unknown option 'options'";
    QTest::newRow("timeout 0") << "postgresql://u@h/l?connect_timeout=0"
                               << "connect_timeout = '0' is outside 1..3600 s";
    QTest::newRow("timeout 3601") << "postgresql://u@h/l?connect_timeout=3601"
                                  << "connect_timeout = '3601' is outside 1..3600 s";
    QTest::newRow("timeout text") << "postgresql://u@h/l?connect_timeout=soon"
                                  << "connect_timeout = 'soon' is outside 1..3600 s";
    QTest::newRow("option injection") << "postgresql://u@h/l?sslmode=require;host=evil"
                                      << "invalid value";
    QTest::newRow("empty option") << "postgresql://u@h/l?sslmode="
                                  << "invalid value";
  }

  void refused() {
    QFETCH(QString, text);
    QFETCH(QString, reason);
    QString message;
    try {
      parseLearningLocation(text);
    } catch (const std::invalid_argument& e) {
      message = QString::fromStdString(e.what());
    }
    QVERIFY2(message.contains(reason), qPrintable(message));
    if (text.contains("secret")) {  // named, but with the password hidden
      QVERIFY2(!message.contains("secret") && message.contains("***"), qPrintable(message));
    } else {
      QVERIFY2(message.contains("'" + text + "'"), qPrintable(message));  // names the value
    }
  }

  void settingRoundTrips() {
    QCOMPARE(mx::app::configuredLearningDatabase(), QString());  // the runner's fresh HOME
    mx::app::setConfiguredLearningDatabase("postgresql://planner@db/learning");
    QCOMPARE(mx::app::configuredLearningDatabase(), QString("postgresql://planner@db/learning"));
    QCOMPARE(QSettings("MillExpert", "MillExpert").value("learning/database").toString(),
             QString("postgresql://planner@db/learning"));  // the GUI's own settings
    mx::app::setConfiguredLearningDatabase({});
    QCOMPARE(mx::app::configuredLearningDatabase(), QString());
  }
};

MX_REGISTER_TEST(TestLearningLocation)
#include "test_learning_location.moc"
