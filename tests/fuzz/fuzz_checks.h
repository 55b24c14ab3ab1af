// What the fuzz targets treat as a finding besides crashes and sanitizer
// reports: an exception that is not skybake::Error, or an Error that does not
// say where the bad input came from. Each finding aborts, which libFuzzer
// records as a crash and saves the input for.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "data_formats/error.h"

namespace skybake::fuzz {

[[noreturn]] inline void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "skybake fuzz finding: %s\n%s\n", what, detail.c_str());
  std::abort();
}

// Bad input must be reported as such, and its message must start with the
// source the caller named, so a user can tell which file is broken.
inline void expectBadInputError(const Error& e, const std::string& source) {
  if (e.kind() != ErrorKind::BadInput) finding("input error not reported as BadInput", e.what());
  if (std::string(e.what()).rfind(source, 0) != 0) {
    finding("error message does not start with the source name", e.what());
  }
}

// Runs `parse` on one input: it may succeed or throw a well-formed BadInput
// error; any other exception is a finding.
template <typename ParseFn>
void expectOnlyBadInputErrors(const std::string& source, ParseFn&& parse) {
  try {
    parse();
  } catch (const Error& e) {
    expectBadInputError(e, source);
  } catch (const std::exception& e) {
    finding("exception other than skybake::Error", e.what());
  } catch (...) {
    finding("exception of a non-standard type", "");
  }
}

}  // namespace skybake::fuzz
