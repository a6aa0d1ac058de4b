#pragma once

#include <string>

#include "cosim/error.hpp"

namespace cosim::testing {

// The message of the cosim::InputError `action` throws; "no error" when it
// throws none.
template <class Action>
std::string input_error_message(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace cosim::testing
