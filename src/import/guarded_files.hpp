// Internal to model import (src/import/): the two rules every file an import opens is held to,
// whoever opens it (facet's own readers, the texture loader, assimp through guarded_io.cpp).
//
// 1. Only regular files. A directory, named pipe, socket or device (/dev/zero) is refused with
//    one line saying what it is; a named pipe would otherwise block the import forever, and a
//    device would feed it bytes without end. Files are opened without blocking and the type is
//    checked on the open descriptor (open_regular_file), so nothing swapped in between can hang.
// 2. Referenced files stay inside the model's folder, after symbolic links are resolved, unless
//    ImportOptions::allow_outside_paths says otherwise: a model from a stranger must not make
//    the program read /etc/passwd or ~/secret.png and draw it.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "facet/import.hpp"

namespace facet::io {

// What a path that is not a regular file is ("a named pipe", "a directory", ...), following
// symbolic links; empty for a regular file or a path that does not exist.
std::string special_file_kind(const std::filesystem::path& path);

// A model path must name a readable regular file: throws "<path>: is a named pipe, not a model
// file", "<path>: no such file" and the like.
void check_model_file(const std::string& path);

// Where one model's references may lead.
class ReferenceRules {
 public:
  ReferenceRules(const std::string& model_file, const ImportOptions& options);

  // Why `path` (a file the model references, as the reader spelled it) must not be opened:
  // "is a named pipe, not a file" or "is outside the model's folder ...". Empty when it may be
  // opened, and for a path that does not exist (the reader reports it missing as before).
  std::string refusal(const std::filesystem::path& path) const;

  const std::string& model_path() const { return model_path_; }

 private:
  std::string model_path_;
  std::filesystem::path folder_;  // canonical; empty if the model's folder cannot be resolved
  std::filesystem::path model_;   // canonical model file (a symlinked model is still the model)
  bool allow_outside_;
};

// Opens a regular file for reading ("rb") without ever blocking: nullptr, and `problem` set to
// what the path is, for a special file, or to the system's reason when it cannot be opened.
std::FILE* open_regular_file(const std::string& path, std::string& problem);

// The whole of a regular file; throws facet::Error "<path>: is a named pipe, not a file" and
// the like.
std::string read_regular_file(const std::string& path);

}  // namespace facet::io
