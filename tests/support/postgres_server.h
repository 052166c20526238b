#pragma once
// A real PostgreSQL server for a test, on loopback: initdb into the test's own temporary folder,
// started on a free port of 127.0.0.1, stopped by its process id (../shared/notes/real-services.md).
// initdb refuses root, so as root the server runs as the "postgres" user of the Debian package, and
// every folder above its data folder is made enterable (search permission only). The binaries are
// those CMake found (MX_PG_BINDIR). start() returns why the server could not start: the test fails
// with it, never skips. After requireTls() the server speaks TLS with the given certificate and
// refuses every connection over TCP that is not encrypted (pg_hba.conf: hostssl trust, hostnossl
// reject).
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSqlDatabase>
#include <QSqlError>
#include <QSqlQuery>
#include <QTemporaryDir>
#include <QThread>
#include <csignal>

#include "support/enterable_folders.h"
#include "support/loopback_port.h"
#include "support/test_certificates.h"

namespace mx::test {

class PostgresServer {
 public:
  PostgresServer() = default;
  PostgresServer(const PostgresServer&) = delete;
  PostgresServer& operator=(const PostgresServer&) = delete;
  ~PostgresServer() { stop(); }

  // Before start(): TLS only, with this certificate and key (copied into the data folder).
  void requireTls(const ServerCertificate& certificate) { tls_ = certificate; }

  // Empty on success, else why the server did not start (with the tail of its log).
  QString start() {
    const QString bindir = QString::fromUtf8(MX_PG_BINDIR);
    if (bindir.isEmpty() || !QFileInfo(bindir + "/initdb").isExecutable())
      return "PostgreSQL's initdb was not found when the build was configured (MX_PG_BINDIR); install the "
             "package postgresql (packaging/bootstrap.sh) and configure again";
    if (!dir_.isValid()) return "cannot create a temporary folder: " + dir_.errorString();
    if (QString why = prepareFolders(); !why.isEmpty()) return why;
    port_ = freeLoopbackPort();
    if (port_ == 0) return "no free TCP port on 127.0.0.1";
    QString output;
    if (!runAsServerUser(bindir + "/initdb",
                         {"-D", data(), "-A", "trust", "-U", "postgres", "-E", "UTF8", "--locale=C", "--no-sync"},
                         120000, &output))
      return "initdb failed: " + output.right(2000);
    // fsync off: the tests kill clients, never the server, and 4000 commits must not wait for a disk.
    QString options =
        QString("-p %1 -k %2 -c listen_addresses=127.0.0.1 -c fsync=off -c max_connections=60").arg(port_).arg(data());
    if (!tls_.cert.isEmpty()) {
      if (QString why = installTls(); !why.isEmpty()) return why;
      options += " -c ssl=on";  // server.crt and server.key in the data folder: the server's defaults
    }
    if (!runAsServerUser(bindir + "/pg_ctl", {"-D", data(), "-o", options, "-l", log(), "-w", "-t", "60", "start"},
                         90000, &output))
      return QString("pg_ctl start failed: %1\nserver log:\n%2").arg(output.right(1000), logTail());
    pid_ = postmasterPid();
    if (pid_ <= 0) return "the server started but wrote no postmaster.pid\nserver log:\n" + logTail();
    return {};
  }

  // Fast shutdown by process id (SIGINT), then SIGKILL if it has not ended within 20 s.
  void stop() {
    if (pid_ <= 0) return;
    ::kill(static_cast<pid_t>(pid_), SIGINT);
    QElapsedTimer clock;
    clock.start();
    while (::kill(static_cast<pid_t>(pid_), 0) == 0 && clock.elapsed() < 20000) QThread::msleep(20);
    if (::kill(static_cast<pid_t>(pid_), 0) == 0) ::kill(static_cast<pid_t>(pid_), SIGKILL);
    pid_ = 0;
  }

  qint64 pid() const { return pid_; }
  int port() const { return port_; }
  QString url(const QString& database = "postgres") const {
    return QString("postgresql://postgres@127.0.0.1:%1/%2").arg(port_).arg(database);
  }

  // Creates an empty database (its name: lower-case letters, digits, '_'); false with why on failure.
  bool createDatabase(const QString& name, QString* why = nullptr) const {
    return exec("CREATE DATABASE " + name, why);
  }

  // Runs one statement in the "postgres" database over a short-lived connection.
  bool exec(const QString& sql, QString* why = nullptr) const {
    const QString connection = QString("mx_test_pg_admin_%1").arg(++counter_);
    bool ok = false;
    {
      QSqlDatabase db = QSqlDatabase::addDatabase("QPSQL", connection);
      db.setHostName("127.0.0.1");
      db.setPort(port_);
      db.setUserName("postgres");
      db.setDatabaseName("postgres");
      ok = db.open();
      QSqlQuery query(db);
      ok = ok && query.exec(sql);
      if (!ok && why != nullptr) *why = query.lastError().text() + db.lastError().text();
      db.close();
    }
    QSqlDatabase::removeDatabase(connection);
    return ok;
  }

  QString logTail() const {
    QFile f(log());
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll().right(3000)) : QString("(no log)");
  }

 private:
  QString data() const { return dir_.filePath("data"); }
  QString log() const { return dir_.filePath("server.log"); }

  static bool isRoot() { return ::geteuid() == 0; }

  // The data folder owned by the server's user, and every folder above it enterable by that user.
  QString prepareFolders() {
    if (!QDir().mkpath(data())) return "cannot create " + data();
    if (!isRoot()) return {};
    const passwd* user = ::getpwnam("postgres");
    if (user == nullptr)
      return "running as root, but there is no user 'postgres' to run the server (package postgresql)";
    if (::chown(QFile::encodeName(data()).constData(), user->pw_uid, user->pw_gid) != 0 ||
        ::chown(QFile::encodeName(dir_.path()).constData(), user->pw_uid, user->pw_gid) != 0)
      return "cannot hand " + data() + " to the user postgres";
    makeEnterableByAll(dir_.path());
    return {};
  }

  static bool runAsServerUser(const QString& program, QStringList arguments, int timeout_ms, QString* output) {
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    if (isRoot()) {
      arguments.prepend(program);
      arguments.prepend("--");
      arguments.prepend("postgres");
      arguments.prepend("-u");
      process.start("runuser", arguments);
    } else {
      process.start(program, arguments);
    }
    const bool finished = process.waitForFinished(timeout_ms);
    *output = QString::fromUtf8(process.readAll());
    if (!finished) {
      process.kill();
      process.waitForFinished();
      *output += QString("\n(timed out after %1 ms)").arg(timeout_ms);
    }
    if (process.error() == QProcess::FailedToStart) *output += "\n(cannot start " + process.program() + ")";
    return finished && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
  }

  // The certificate and key in the data folder, the key readable by the server's user only (the server
  // refuses a key others can read), and pg_hba.conf that accepts TCP connections with TLS only.
  QString installTls() const {
    const QString cert = data() + "/server.crt", key = data() + "/server.key";
    if (!QFile::copy(tls_.cert, cert) || !QFile::copy(tls_.key, key))
      return "cannot copy the server certificate and key into " + data();
    if (!QFile::setPermissions(key, QFile::ReadOwner | QFile::WriteOwner)) return "cannot protect " + key;
    if (isRoot()) {
      const passwd* user = ::getpwnam("postgres");
      for (const QString& file : {cert, key})
        if (user == nullptr || ::chown(QFile::encodeName(file).constData(), user->pw_uid, user->pw_gid) != 0)
          return "cannot hand " + file + " to the user postgres";
    }
    QFile hba(data() + "/pg_hba.conf");
    const QByteArray rules =
        "local all all trust\n"
        "hostssl all all 127.0.0.1/32 trust\n"
        "hostnossl all all 127.0.0.1/32 reject\n";
    if (!hba.open(QIODevice::WriteOnly | QIODevice::Truncate) || hba.write(rules) != rules.size())
      return "cannot write " + hba.fileName();
    return {};
  }

  qint64 postmasterPid() const {
    QFile f(data() + "/postmaster.pid");
    return f.open(QIODevice::ReadOnly) ? f.readLine().trimmed().toLongLong() : 0;
  }

  QTemporaryDir dir_;
  ServerCertificate tls_;
  int port_ = 0;
  qint64 pid_ = 0;
  static inline int counter_ = 0;
};

}  // namespace mx::test
