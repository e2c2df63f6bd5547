// How the program imports a model file: the library's import_scene, with assimp's own printing
// kept off the program's output.
#pragma once

#include <string>

#include "facet/import.hpp"
#include "facet/scene.hpp"

namespace facet::cli {

// import_scene(path), with std::cout and std::cerr silenced while it runs: a few of assimp's
// parsers print straight to them (the OpenDDL parser of OpenGEX files, for one), which would
// make a bad file two lines of error instead of facet's one. The program writes its own output
// with stdio, never through these streams, and imports on one thread, so nothing of its own is
// lost. Throws facet::Error as import_scene does.
// allow_outside_paths: ImportOptions::allow_outside_paths; timeout_seconds (--import-timeout):
// ImportOptions::import_time_limit_seconds, 0 for none; throws facet::Error if negative.
Scene import_model(const std::string& path, bool allow_outside_paths = false,
                   double timeout_seconds = 60.0);
// The same with every import option (their warn left as the library's: one line on stderr);
// import_time_limit_seconds is checked as --import-timeout.
Scene import_model(const std::string& path, const ImportOptions& options);

}  // namespace facet::cli
