#include "frf/frf_dataset.h"

namespace mx {

std::string_view frfQuantityName(FrfQuantity q) {
  switch (q) {
    case FrfQuantity::Receptance:
      return "receptance";
    case FrfQuantity::Mobility:
      return "mobility";
    case FrfQuantity::Accelerance:
      return "accelerance";
  }
  return "";
}

std::string_view frfDirectionName(FrfDirection d) {
  switch (d) {
    case FrfDirection::X:
      return "x";
    case FrfDirection::Y:
      return "y";
    case FrfDirection::Z:
      return "z";
  }
  return "";
}

}  // namespace mx
