// The check every config-refusal test makes: the text is refused as bad
// input, with a message naming the source and holding the expected parts.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>

#include "data_formats/config/config.h"
#include "data_formats/error.h"

namespace skybake::test {

// The source name refused configs are parsed under.
inline constexpr const char* kRejectedConfigSource = "test.toml";

// Parses `text` (spectrum files relative to `spectrum_directory`) expecting
// a BadInput error whose message names test.toml and contains every string
// in `fragments`.
inline void expectConfigRejected(const std::string& text, std::initializer_list<std::string> fragments,
                                 const std::filesystem::path& spectrum_directory = {}) {
  try {
    parseConfig(text, kRejectedConfigSource, spectrum_directory);
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    const std::string message = e.what();
    EXPECT_NE(message.find(kRejectedConfigSource), std::string::npos) << message;
    for (const std::string& f : fragments) EXPECT_NE(message.find(f), std::string::npos) << message;
  }
}

}  // namespace skybake::test
