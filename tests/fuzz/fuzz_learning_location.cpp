// Fuzz target of the learning-database location (parseLearningLocation): a file path or a
// postgresql:// URL from a CLI flag or the user's setting. A refused text says why in an
// std::invalid_argument and never shows a password; an accepted URL has a host, a database, a port in
// 1..65535 and connect options free of ';'-injected keys, and its display form parses back to the
// same server.
#include <QString>
#include <QStringList>
#include <cstdint>
#include <stdexcept>

#include "fuzz_check.h"
#include "services/learning_location.h"

namespace {

void checkAcceptedUrl(const mx::app::LearningLocation& l) {
  using mx::fuzz::require;
  require(!l.host.isEmpty() && !l.database.isEmpty(), "an accepted URL has a host and a database");
  require(l.port >= 1 && l.port <= 65535, "an accepted URL's port is in 1..65535");
  for (const QString& option : l.connect_options.split(';'))
    require(option.count('=') == 1, "each connect option is one key=value");
  const mx::app::LearningLocation again = mx::app::parseLearningLocation(l.display());
  require(again.host == l.host && again.port == l.port && again.database == l.database && again.user == l.user,
          "the display form names the same server");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const QString text = QString::fromUtf8(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
  try {
    const mx::app::LearningLocation l = mx::app::parseLearningLocation(text);
    if (l.backend == mx::app::LearningBackend::PostgreSql)
      checkAcceptedUrl(l);
    else
      mx::fuzz::require(l.file == text, "a file location is the text itself");
  } catch (const std::invalid_argument& e) {
    const QString message = QString::fromUtf8(e.what());
    mx::fuzz::require(message.startsWith("learning database '"), "a refusal names the location");
    // "postgresql://user:password@": the user information with its password is never repeated.
    const qsizetype scheme_end = text.indexOf("://");
    const qsizetype at = text.indexOf('@');
    const QString userinfo = scheme_end > 0 && at > scheme_end ? text.left(at + 1) : QString();
    if (userinfo.mid(scheme_end + 3).contains(':') && !userinfo.mid(scheme_end + 3).contains(QLatin1Char('/')) &&
        !userinfo.endsWith(":***@"))
      mx::fuzz::require(!message.contains(userinfo), "a refusal never shows the password");
  }
  return 0;
}
