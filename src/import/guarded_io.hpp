// Internal to the assimp importer (import_assimp.cpp): the file access assimp is given, so that
// every file it opens (the model, a glTF .bin buffer, an OBJ's .mtl library, ...) is held to the
// rules of guarded_files.hpp. assimp's own file access would block forever on a named pipe and
// follow any path a model names.
#pragma once

#include <assimp/IOSystem.hpp>
#include <string>
#include <vector>

#include "import/guarded_files.hpp"

namespace facet::io {

class GuardedIOSystem : public Assimp::IOSystem {
 public:
  explicit GuardedIOSystem(const ReferenceRules& rules) : rules_(rules) {}

  // A refused file neither exists nor opens, as a missing one, and is remembered (refusals).
  bool Exists(const char* path) const override;
  Assimp::IOStream* Open(const char* path, const char* mode) override;
  void Close(Assimp::IOStream* stream) override;
  char getOsSeparator() const override { return '/'; }

  // One "<model>: referenced file <path> <why>" line per refused path, in the order met.
  const std::vector<std::string>& refusals() const { return refusals_; }

 private:
  bool refused(const std::string& path, const std::string& problem) const;

  const ReferenceRules& rules_;
  mutable std::vector<std::string> refusals_;
  mutable std::vector<std::string> refused_paths_;
};

}  // namespace facet::io
