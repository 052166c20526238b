#pragma once
// The "What's This" texts of the quantities the window names by symbol (ROS, ΔN_s, q*, q**, η, J_c):
// one plain-text definition each, with the paper and equation it comes from. The readouts, the ranking
// table, the simulation and monitoring indicators and the control views all show these texts, and
// docs/user-guide.md ("Glossary") quotes them word for word (a test compares them), so that the window
// and the guide say the same.
#include <QString>
#include <array>

namespace mx::widgets {

enum class Term { Ros, DeltaNs, QStar, QStarStar, Eta, Jc };

inline constexpr std::array<Term, 6> kGlossaryTerms = {Term::Ros,       Term::DeltaNs, Term::QStar,
                                                       Term::QStarStar, Term::Eta,     Term::Jc};

QString termSymbol(Term term);    // as the window labels it: "ROS", "ΔN_s", "q*", "q**", "η", "J_c"
QString glossaryText(Term term);  // 1-3 plain sentences, citing the source

}  // namespace mx::widgets
