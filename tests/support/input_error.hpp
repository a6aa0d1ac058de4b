#pragma once

#include <gtest/gtest.h>

#include <iostream>
#include <string>

#include "cosim/error.hpp"

// The cosim::InputError a test's action throws.
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

// The InputError `action` throws, printed so the test log shows what a user
// would read; a test failure when nothing is thrown.
template <class Action>
InputError input_error_from(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    std::cout << "    InputError: " << error.what() << '\n';
    return error;
  }
  ADD_FAILURE() << "expected an InputError, nothing was thrown";
  return InputError("nothing was thrown");
}

}  // namespace cosim::testing
