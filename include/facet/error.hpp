// facet::Error: the one exception type the library throws.
// Messages name what went wrong and where (file, line, index), ready to print as one line.
#pragma once

#include <stdexcept>
#include <string>

namespace facet {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace facet
