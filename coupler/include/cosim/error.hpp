#pragma once

#include <stdexcept>
#include <string>

#include "cosim/exit_codes.hpp"

namespace cosim {

// Base of every error that ends a run: it carries the exit code the process
// should return (architecture.md §6).
class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

// Where in an input file something was found; line and column are 1-based,
// zero when unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// Bad input: a config, mesh or argument that cannot be used. The message
// reads `file:line:col: key 'a.b.c': what is wrong`, each part abbreviated
// in the middle when absurdly long.
class InputError : public Error {
 public:
  InputError(const SourceLocation& where, const std::string& key_path, const std::string& what);
  explicit InputError(const std::string& what);

  const SourceLocation& where() const { return where_; }
  const std::string& key_path() const { return key_path_; }

 private:
  SourceLocation where_;
  std::string key_path_;
};

// A peer (participant or coupler) sent something that breaks the protocol,
// or stopped answering. The message names the peer.
class ProtocolError : public Error {
 public:
  ProtocolError(const std::string& peer, const std::string& what)
      : Error(ExitCode::participant_failed, "from '" + peer + "': " + what), peer_(peer) {}
  const std::string& peer() const { return peer_; }

 private:
  std::string peer_;
};

// A solver's state became unusable (non-finite values, unrecoverable CFL).
class NumericalError : public Error {
 public:
  explicit NumericalError(const std::string& what) : Error(ExitCode::numerical_failure, what) {}
};

}  // namespace cosim
