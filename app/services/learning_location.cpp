#include "services/learning_location.h"

#include <QRegularExpression>
#include <QSettings>
#include <QUrl>
#include <QUrlQuery>
#include <algorithm>
#include <array>
#include <stdexcept>

namespace mx::app {

namespace {

constexpr std::array<const char*, 6> kUrlOptions{"sslmode", "sslrootcert",     "sslcert",
                                                 "sslkey",  "connect_timeout", "target_session_attrs"};
constexpr int kDefaultConnectTimeoutS = 10;  // a shop server that does not answer must not hang a save
constexpr int kMaxConnectTimeoutS = 3600;

[[noreturn]] void refuse(const QString& text, const QString& why) {
  throw std::invalid_argument(
      QString("learning database '%1': %2").arg(redactedLearningLocation(text), why).toStdString());
}

QString allowedOptions() {
  QStringList names;
  for (const char* name : kUrlOptions) names << QString::fromLatin1(name);
  return names.join(", ");
}

// libpq's connection string separates its key=value pairs by spaces: a value with a space (a
// certificate under "/home/Jane Doe/"), a quote or a backslash goes in single quotes, those two escaped.
QString conninfoValue(QString value) {
  static const QRegularExpression needs_quotes(R"([\s'\\])");
  if (!value.contains(needs_quotes)) return value;
  value.replace('\\', QLatin1String("\\\\")).replace('\'', QLatin1String("\\'"));
  return '\'' + value + '\'';
}

QString connectOptions(const QString& text, const QUrlQuery& query) {
  QStringList options;
  bool timeout_given = false;
  for (const auto& [key, value] : query.queryItems(QUrl::FullyDecoded)) {
    if (key == QLatin1String("password"))
      refuse(text, "a password is not accepted in the URL; give it in PGPASSWORD or ~/.pgpass");
    if (std::find(kUrlOptions.begin(), kUrlOptions.end(), key) == kUrlOptions.end())
      refuse(text, QString("unknown option '%1' (allowed: %2)").arg(key, allowedOptions()));
    if (key == QLatin1String("connect_timeout")) {
      bool ok = false;
      const int seconds = value.toInt(&ok);
      if (!ok || seconds < 1 || seconds > kMaxConnectTimeoutS)
        refuse(text, QString("connect_timeout = '%1' is outside 1..%2 s").arg(value).arg(kMaxConnectTimeoutS));
      timeout_given = true;
    }
    if (value.contains(';') || value.contains('=') || value.isEmpty())
      refuse(text, QString("option %1 has the invalid value '%2'").arg(key, value));
    options << QString("%1=%2").arg(key, conninfoValue(value));
  }
  if (!timeout_given) options << QString("connect_timeout=%1").arg(kDefaultConnectTimeoutS);
  return options.join(';');
}

LearningLocation parseUrl(const QString& text) {
  const QUrl url(text, QUrl::StrictMode);
  if (!url.isValid()) {
    // QUrl's own message may quote the user information, and so a password: shown only without one.
    const QString detail =
        text.contains('@') ? QString("postgresql://[user@]host[:port]/database[?options]") : url.errorString();
    refuse(text, QString("not a valid URL (%1)").arg(detail));
  }
  if (!url.password().isEmpty())
    refuse(text, "a password is not accepted in the URL; give it in PGPASSWORD or ~/.pgpass");
  LearningLocation l;
  l.backend = LearningBackend::PostgreSql;
  l.user = url.userName(QUrl::FullyDecoded);
  l.host = url.host(QUrl::FullyDecoded);
  if (l.host.isEmpty()) refuse(text, "no host (postgresql://user@host[:port]/database)");
  const int port = url.port(5432);
  if (port < 1 || port > 65535) refuse(text, QString("port %1 is outside 1..65535").arg(port));
  l.port = port;
  l.database = url.path(QUrl::FullyDecoded).mid(1);
  if (l.database.isEmpty() || l.database.contains('/'))
    refuse(text, "no database name (postgresql://user@host[:port]/database)");
  l.connect_options = connectOptions(text, QUrlQuery(url));
  return l;
}

// The GUI's settings (organisation and application "MillExpert"), whichever program asks.
constexpr const char* kOrganisation = "MillExpert";
constexpr const char* kApplication = "MillExpert";

}  // namespace

bool isLearningUrl(const QString& text) {
  return text.startsWith("postgresql://", Qt::CaseInsensitive) || text.startsWith("postgres://", Qt::CaseInsensitive);
}

QString redactedLearningLocation(QString text) {
  static const QRegularExpression userPassword("(://[^/@:]*:)[^/@]*@");
  static const QRegularExpression passwordOption("(password=)[^&]*");
  return text.replace(userPassword, "\\1***@").replace(passwordOption, "\\1***");
}

QString LearningLocation::display() const {
  if (backend == LearningBackend::Sqlite) return file;
  QUrl url;
  url.setScheme("postgresql");
  url.setUserName(user);
  url.setHost(host);
  url.setPort(port);
  url.setPath("/" + database);
  return url.toString();
}

LearningLocation parseLearningLocation(const QString& text) {
  if (text.trimmed().isEmpty()) refuse(text, "no file name or URL given");
  if (isLearningUrl(text.trimmed())) return parseUrl(text.trimmed());
  LearningLocation l;
  l.file = text;
  return l;
}

QString configuredLearningDatabase() {
  return QSettings(kOrganisation, kApplication).value(kLearningDatabaseSetting).toString();
}

void setConfiguredLearningDatabase(const QString& location) {
  QSettings settings(kOrganisation, kApplication);
  if (location.isEmpty())
    settings.remove(kLearningDatabaseSetting);
  else
    settings.setValue(kLearningDatabaseSetting, location);
}

}  // namespace mx::app
