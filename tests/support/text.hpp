// Small text checks the tests share.
#pragma once

#include <string>

namespace facet::test {

// Whether `part` occurs in `text`.
inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace facet::test
