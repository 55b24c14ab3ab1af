// The one failure mechanism of skybake's libraries: they throw skybake::Error,
// and only the command line turns it into a message and an exit status.
#pragma once

#include <stdexcept>
#include <string>

namespace skybake {

enum class ErrorKind {
  // The user gave something unusable (a config value, a file, a flag, an
  // output location that cannot be written, a full disk, sizes beyond the
  // machine's memory): exit 2.
  BadInput,
  // skybake itself failed (a bug, an allocation failing after the memory
  // check passed, a library that cannot do what skybake asks): exit 1.
  Internal,
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }

 private:
  ErrorKind kind_;
};

// A message of the form "<where>: <what> = <value>: <reason>", the shape every
// input error takes so users can find the offending line.
[[noreturn]] inline void throwBadInput(const std::string& message) { throw Error(ErrorKind::BadInput, message); }

}  // namespace skybake
