// The learning database (app/services/learning_database.h) on a PostgreSQL server that accepts TLS only
// (support/postgres_server.h, requireTls): the URL's sslmode and sslrootcert reach libpq, the session
// is encrypted (pg_stat_ssl on the database's own connection), and libpq refuses a plain connection,
// an authority that did not sign the server's certificate and a host name the certificate does not
// name, each with a message that names the URL.
#include <QDir>
#include <QUrl>

#include "services/learning_database.h"
#include "support/error_message.h"
#include "support/learning_backends.h"
#include "support/test_certificates.h"
#include "test_registry.h"

using mx::app::LearningDatabase;
using mx::app::LearningDatabaseError;

class TestLearningTls : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    // The client's copy of the authority in a folder with a space: the path reaches libpq quoted.
    const QString client = dir_.filePath("client certs");
    mx::test::CertificateAuthority shop_ca, other_ca;
    mx::test::ServerCertificate server_cert;
    QString why = mx::test::makeCertificateAuthority(client, "shop-ca", &shop_ca);
    if (why.isEmpty()) why = mx::test::makeCertificateAuthority(client, "other-ca", &other_ca);
    if (why.isEmpty()) why = mx::test::makeServerCertificate(dir_.filePath("server"), shop_ca, &server_cert);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    shop_ca_ = shop_ca.cert;
    other_ca_ = other_ca.cert;
    server_.requireTls(server_cert);
    why = server_.start();
    QVERIFY2(why.isEmpty(), qPrintable("the PostgreSQL server did not start: " + why));
    QVERIFY2(server_.createDatabase("learning", &why), qPrintable(why));
  }

  void verifiedSessionIsEncrypted() {
    LearningDatabase db(url("127.0.0.1", "verify-full", shop_ca_));
    QCOMPARE(db.count(), 0);
    QCOMPARE(mx::test::rawScalar(db, "SELECT ssl FROM pg_stat_ssl WHERE pid = pg_backend_pid()").toBool(), true);
    const QString version =
        mx::test::rawScalar(db, "SELECT version FROM pg_stat_ssl WHERE pid = pg_backend_pid()").toString();
    QVERIFY2(version.startsWith("TLSv1."), qPrintable(version));
  }

  void requireEncryptsWithoutAnAuthority() {
    LearningDatabase db(url("127.0.0.1", "require", {}));
    QCOMPARE(mx::test::rawScalar(db, "SELECT ssl FROM pg_stat_ssl WHERE pid = pg_backend_pid()").toBool(), true);
  }

  void refused_data() {
    QTest::addColumn<QString>("host");
    QTest::addColumn<QString>("sslmode");
    QTest::addColumn<bool>("other_authority");
    QTest::addColumn<QString>("reason");
    QTest::newRow("no TLS") << "127.0.0.1"
                            << "disable" << false << "no encryption";
    QTest::newRow("unknown authority") << "127.0.0.1"
                                       << "verify-full" << true << "certificate verify failed";
    QTest::newRow("other host name") << "localhost"
                                     << "verify-full" << false << "does not match host name \"localhost\"";
  }

  void refused() {
    QFETCH(QString, host);
    QFETCH(QString, sslmode);
    QFETCH(bool, other_authority);
    QFETCH(QString, reason);
    const QString location = url(host, sslmode, other_authority ? other_ca_ : shop_ca_);
    const QString message = mx::test::messageOf<LearningDatabaseError>([&] { LearningDatabase db(location); });
    QVERIFY2(!message.isNull(), "the connection was accepted");
    QVERIFY2(message.contains(QString("postgresql://postgres@%1:%2/learning").arg(host).arg(server_.port())),
             qPrintable(message));
    QVERIFY2(message.contains(reason), qPrintable(message));
  }

 private:
  QString url(const QString& host, const QString& sslmode, const QString& root_cert) const {
    QString text =
        QString("postgresql://postgres@%1:%2/learning?sslmode=%3").arg(host).arg(server_.port()).arg(sslmode);
    if (!root_cert.isEmpty()) text += "&sslrootcert=" + QString::fromLatin1(QUrl::toPercentEncoding(root_cert, "/"));
    return text;
  }

  QTemporaryDir dir_;
  mx::test::PostgresServer server_;
  QString shop_ca_, other_ca_;
};

MX_REGISTER_TEST(TestLearningTls)
#include "test_learning_tls.moc"
