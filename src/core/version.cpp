// The version the library was built as (see facet/version.hpp).
#include "facet/version.hpp"

namespace facet {

const char* version() { return FACET_VERSION; }

}  // namespace facet
