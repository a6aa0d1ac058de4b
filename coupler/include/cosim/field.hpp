#pragma once

#include <cstdint>
#include <limits>
#include <string>

// Field descriptors: what a participant writes and reads.
namespace cosim {

// Intensive fields (pressure, velocity, porosity) are mapped consistently:
// target values are weighted averages. Extensive fields (mass, momentum,
// impulse, force, volume) are mapped conservatively: totals are kept.
enum class Quantity : std::uint8_t { intensive, extensive };

// How a field relates to the coupling window.
enum class TimeTreatment : std::uint8_t {
  state,     // the value at the end of the window (last write wins)
  integral,  // a rate written every sub-step; the window's time integral is sent
};

struct FieldSpec {
  std::string name;
  std::string mesh;
  int components = 1;
  std::string unit;  // SI, e.g. "Pa", "m/s", "kg m/s"
  Quantity quantity = Quantity::intensive;
  TimeTreatment time = TimeTreatment::state;
  bool allow_nonfinite = false;
  double lower_bound = -std::numeric_limits<double>::infinity();
  double upper_bound = std::numeric_limits<double>::infinity();
  // A read the job may leave out: the participant then keeps the default and
  // learns it from Participant::is_sent() (a field only some jobs provide).
  bool optional = false;
};

const char* to_string(Quantity quantity);
const char* to_string(TimeTreatment time);

}  // namespace cosim
