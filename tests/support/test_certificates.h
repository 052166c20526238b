#pragma once
// Certificates for a test's TLS server, made with the openssl command line in the test's own folder:
// a certificate authority of its own, and a server certificate it signs for the IP address 127.0.0.1
// (subjectAltName, so that libpq's sslmode=verify-full accepts the host 127.0.0.1 and refuses any
// other name). EC P-256 keys, valid two days. makeCertificateAuthority() and makeServerCertificate()
// return why openssl failed: the test fails with it, never skips.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>

namespace mx::test {

struct CertificateAuthority {
  QString cert;  // PEM, what a client names in sslrootcert
  QString key;
};

struct ServerCertificate {
  QString cert;
  QString key;
};

namespace detail {

inline QString runOpenssl(const QStringList& arguments) {
  QProcess process;
  process.setProcessChannelMode(QProcess::MergedChannels);
  process.start("openssl", arguments);
  if (!process.waitForFinished(60000)) {
    process.kill();
    process.waitForFinished();
    return "openssl " + arguments.join(' ') + ": did not finish within 60 s";
  }
  if (process.error() == QProcess::FailedToStart) return "cannot start openssl (package openssl)";
  if (process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0)
    return "openssl " + arguments.join(' ') + ": " + QString::fromUtf8(process.readAll()).right(1500);
  return {};
}

inline QStringList newKeyArguments(const QString& key) {
  return {"-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes", "-keyout", key};
}

}  // namespace detail

// A self-signed authority named `name`, its files in `folder` (created when missing).
inline QString makeCertificateAuthority(const QString& folder, const QString& name, CertificateAuthority* out) {
  if (!QDir().mkpath(folder)) return "cannot create " + folder;
  const QDir dir(folder);
  out->cert = dir.filePath(name + ".crt");
  out->key = dir.filePath(name + ".key");
  QStringList arguments{"req", "-x509", "-days", "2", "-subj", "/CN=" + name, "-out", out->cert};
  arguments << detail::newKeyArguments(out->key);
  return detail::runOpenssl(arguments);
}

// A certificate for the server at 127.0.0.1, signed by `authority`, its files in `folder`.
inline QString makeServerCertificate(const QString& folder, const CertificateAuthority& authority,
                                     ServerCertificate* out) {
  if (!QDir().mkpath(folder)) return "cannot create " + folder;
  const QDir dir(folder);
  out->cert = dir.filePath("server.crt");
  out->key = dir.filePath("server.key");
  const QString request = dir.filePath("server.csr"), extensions = dir.filePath("server.ext");
  QFile ext(extensions);
  if (!ext.open(QIODevice::WriteOnly) || ext.write("subjectAltName = IP:127.0.0.1\n") < 0)
    return "cannot write " + extensions;
  ext.close();
  QStringList request_arguments{"req", "-subj", "/CN=127.0.0.1", "-out", request};
  request_arguments << detail::newKeyArguments(out->key);
  if (QString why = detail::runOpenssl(request_arguments); !why.isEmpty()) return why;
  return detail::runOpenssl({"x509", "-req", "-in", request, "-CA", authority.cert, "-CAkey", authority.key,
                             "-CAcreateserial", "-days", "2", "-extfile", extensions, "-out", out->cert});
}

}  // namespace mx::test
