#include "glossary.h"

#include <QCoreApplication>

namespace mx::widgets {

QString termSymbol(Term term) {
  switch (term) {
    case Term::Ros:
      return QStringLiteral("ROS");
    case Term::DeltaNs:
      return QStringLiteral("\u0394N_s");
    case Term::QStar:
      return QStringLiteral("q*");
    case Term::QStarStar:
      return QStringLiteral("q**");
    case Term::Eta:
      return QStringLiteral("\u03b7");
    case Term::Jc:
      return QStringLiteral("J_c");
  }
  return {};
}

// Plain text (no "<"): QWhatsThis would take a tag-like text for rich text.
QString glossaryText(Term term) {
  auto tr = [](const char* text) { return QCoreApplication::translate("mx::widgets::Glossary", text); };
  switch (term) {
    case Term::Ros:
      return tr(
          "ROS (robustness) [\u2013]: the smallest relative change of spindle speed and depth that reaches the "
          "margined stability boundary \u03b1 b_lim,\u03b4(N). 1 means the depth could double; a negative ROS "
          "means the point is unstable. Pareto paper, eq. 13 (docs/fidelity.md, \"Delta N_s and ROS\").");
    case Term::DeltaNs:
      return tr(
          "\u0394N_s (spindle speed security change) [rpm]: how far the spindle speed can drift at this depth "
          "before the cut reaches the lobes, the smaller of the distances to the left and to the right. It is the "
          "third term of the tool cost C; Rubio, De la Sen & Ibeas 2006, section 3.B and eq. 13.");
    case Term::QStar:
      return tr(
          "q*: a tool's cost-minimising operating point (speed N*, depth b*, feed per tooth s_t*), where the tool "
          "cost C = c1 P/P_av + c2 MRR_max/MRR + c3 \u0394N_s,max/\u0394N_s is smallest over the admissible space. "
          "Rule 4 ranks the tools by that minimum; Rubio, De la Sen & Ibeas 2006, eq. 13.");
    case Term::QStarStar:
      return tr(
          "q**: the refined point of the selected tool: a search around q*, seeded with its best points by C, "
          "that minimises C_resultant = c1r C + c2r C_t + c3r C_f from time-domain simulations. Rule 5; Rubio, "
          "De la Sen & Ibeas 2006, eq. 18-20.");
    case Term::Eta:
      return tr(
          "\u03b7 (chatter indicator) [\u2013]: the largest dynamic cutting force over the largest static one, "
          "max|F_dynamic| / max|F_static|, in the time-domain simulation of the point. About 1 when the cut is "
          "stable; chatter from 1.3. Rubio, De la Sen & Ibeas 2006, eq. 11.");
    case Term::Jc:
      return tr(
          "J_c (force-control cost) [N\u00b7s]: the area between the continuous plant force and the linear "
          "interpolation of its samples, i.e. the ripple between samples under the \u03b2-FROH hold; smaller is "
          "better, and its minimum over \u03b2 picks the hold. Rubio, De la Sen & Ibeas 2006, eq. 34 and figure 13.");
  }
  return {};
}

}  // namespace mx::widgets
