#include "cosim/field.hpp"

namespace cosim {

const char* to_string(Quantity quantity) {
  return quantity == Quantity::intensive ? "intensive" : "extensive";
}

const char* to_string(TimeTreatment time) {
  return time == TimeTreatment::state ? "state" : "integral";
}

}  // namespace cosim
